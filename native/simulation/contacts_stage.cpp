// Stage 4 of a step: contact forces, block by block of rows (see force_stage): every sum has an
// order fixed by the list alone, so the result does not depend on the number of threads, and no
// floating-point atomics are needed.
#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <vector>

#include <omp.h>

#include "core/contact_lanes.hpp"
#include "simulation/late_pass.hpp"
#include "simulation/particle_finish.hpp"
#include "simulation/simulation.hpp"
#include "simulation/wall_pass.hpp"

namespace talus {

namespace {

// A list entry found touching by the first pass over a stretch of rows (see force_stage).
struct TouchingEntry {
  Vec2 d; // r_i - r_j (the image of j)
  std::uint32_t entry;
  std::uint32_t slot; // its deferred slot, or no_slot if its second particle is in the block
};
constexpr std::uint32_t no_slot = ~std::uint32_t{0};
// Rows per stretch: their particles' data stays in the L1 cache between the two passes.
constexpr std::ptrdiff_t stretch_rows = NeighbourList::stretch_rows;

// What the first pass learns of an entry, for the candidates.
struct EntryGap {
  double dist2, reach;
  std::uint32_t i, j;
};

// Forces between particles, block by block (NeighbourList: force blocks). A block first sets the
// force of its own particles to their weight (unless the last stage did: `forces_started`), then
// adds each touching pair's force to both partners in entry order, except that a partner beyond
// the block gets its share later, from a deferred slot. A block writes only its own particles,
// so blocks run side by side, and the order of every sum is fixed by the list alone: results do
// not depend on the thread count. The threads take the blocks one at a time, the longest first
// by the time each took in the last stages (force_block_order), so that a thread that finishes
// early takes more and the last ones, when a thread may wait, are short: the blocks' times change
// from step to step by more than a fixed share per thread could follow (docs/performance.md,
// "Force blocks").
// A block goes through its rows by stretches of 64, in two passes. The first tests the entries
// and writes down the touching ones, with masks instead of a branch per entry: in a disordered
// packing which neighbours touch follows no pattern a branch predictor can learn. The second
// computes the touching pairs' forces. The sums are the same, in the same order, as in one pass
// that tests every entry and branches. The first pass tests only the candidates (ContactCandidates:
// entries that may touch before the grains move on; the others cannot touch and keep a zero
// history); with `refresh` it tests every entry and writes the candidates down again, by stretch,
// from the stretch's first entry on. The touching entries found, and so the results, are the same
// either way. `done.range(first, last)` is called for the particles of a stretch whose forces are
// complete once its rows are done (rows after them never name them), by runs between late ones; the
// late ones (NeighbourList::late) are done in the late pass (finish_late) after every block and
// wall contact, in the same parallel region. Its answers are merged.
template <class N, class T, class Done>
std::pair<double, PassReport>
force_stage(Particles& p, NeighbourList& list, ContactCandidates& near, bool refresh,
            const PairTable& pairs, const Domain& domain, Vec2 gravity, Segments& walls,
            std::vector<PairForce>& deferred, std::vector<PairForce>& wall_force, double dt,
            const Done& done, std::vector<std::uint64_t>& block_work,
            std::vector<std::ptrdiff_t>& order, bool forces_started, int threads) {
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  const auto rows = static_cast<std::ptrdiff_t>(list.block_rows);
  const auto blocks = static_cast<std::ptrdiff_t>(list.block_first_slot.size()) - 1;
  const std::size_t stretches_per_block =
      static_cast<std::size_t>((rows + stretch_rows - 1) / stretch_rows);
  if (refresh) {
    near.entry.resize(list.pair_count());
    near.slot.resize(list.pair_count());
    near.count.resize(static_cast<std::size_t>(blocks) * stretches_per_block);
  }
  std::uint32_t* near_entry = near.entry.data();
  std::uint32_t* near_slot = near.slot.data();
  std::uint32_t* near_count = near.count.data();
  const double near_skin = near.skin;
  const Kind* kind = p.kind.data();
  if (block_work.size() != static_cast<std::size_t>(blocks)) block_work.assign(blocks, 0);
  const Vec2 box = domain.size();
  // With one material every contact has the same pair parameters: they are put in lanes once,
  // not for every two contacts.
  const bool one_material = pairs.material_count() == 1;
  const PairLanes uniform = one_material ? pair_lanes(pairs(0, 0), pairs(0, 0))
                                         : pair_lanes(PairParameters{}, PairParameters{});
  double worst = 0.0, farthest2 = 0.0;
  bool finite = true;
  force_block_order(block_work, order);
  const auto late = static_cast<std::ptrdiff_t>(list.late.size());
#pragma omp parallel num_threads(threads) reduction(max : worst, farthest2) reduction(&& : finite)
  {
#pragma omp for schedule(dynamic, 1) nowait
    for (std::ptrdiff_t taken = 0; taken < blocks; ++taken) {
      const std::ptrdiff_t b = order[static_cast<std::size_t>(taken)];
      const auto block_start = std::chrono::steady_clock::now();
      // per thread, kept from step to step: it grows only when a stretch has more entries than
      // any before it, so steps after the first few allocate nothing
      thread_local std::vector<TouchingEntry> touching;
      const std::ptrdiff_t first = b * rows, last = std::min(n, first + rows);
      if (!forces_started) // else the last stage's `done` started them
        for (std::ptrdiff_t k = first; k < last; ++k)
          start_forces(p, k, gravity, p.force.data(), p.torque.data());
      std::uint32_t slot = list.block_first_slot[b];
      // the block's late particles, walked alongside the rows (no per-row lookup)
      auto next_late = std::lower_bound(list.late.begin(), list.late.end(), first);
      // the arrays by plain pointers: stores through one cannot move another (no reloads)
      const Vec2* position = p.position.data();
      const double* radius = p.radius.data();
      const std::uint32_t* offset = list.row_offset.data();
      const std::uint32_t* neighbour = list.neighbour.data();
      const ImageShift* images = list.image.data();
      double* history = list.history.data();
      PairForce* slots = deferred.data();
      const std::uint8_t* row_in_stretch = list.entry_row.data();
      const double* mass = p.mass.data();
      const Vec2* velocity = p.velocity.data();
      const double* spin = p.angular_velocity.data();
      const std::uint16_t* material = p.material.data();
      // a deferred entry that does not touch leaves a zero in its slot
      std::fill(slots + slot, slots + list.block_first_slot[b + 1], PairForce{});
      for (std::ptrdiff_t r0 = first; r0 < last; r0 += stretch_rows) {
        const std::ptrdiff_t r1 = std::min(last, r0 + stretch_rows);
        if (touching.size() < offset[r1] - offset[r0]) touching.resize(offset[r1] - offset[r0]);
        TouchingEntry* found = touching.data();
        // first pass: the touching entries; the others lose their history (masks, no branches)
        std::size_t count = 0;
        // entry e's geometry; it is written down if it touches (its deferred slot is `to`)
        const auto test = [&](std::uint32_t e, std::uint32_t to) {
          const auto i = static_cast<std::uint32_t>(r0 + row_in_stretch[e]);
          const std::uint32_t j = neighbour[e];
          Vec2 rj = position[j];
          const ImageShift image = images[e];
          if (image.sx != 0 || image.sy != 0) [[unlikely]] // across a periodic boundary
            rj += Vec2{image.sx * box.x, image.sy * box.y};
          const Vec2 d = position[i] - rj;
          const double dist2 = norm2(d);
          const double reach = radius[i] + radius[j];
          // "not beyond reach" rather than "within reach": a NaN distance counts as touching, so
          // that it reaches the forces and the finite check (as with the one-pass stage)
          const bool touches = !(dist2 >= reach * reach) & (dist2 != 0.0);
          found[count] = {d, e, to};
          count += touches;
          const std::uint64_t keep = 0ull - static_cast<std::uint64_t>(touches);
          history[e] = std::bit_cast<double>(std::bit_cast<std::uint64_t>(history[e]) & keep);
          return EntryGap{dist2, reach, i, j};
        };
        const std::uint32_t base = offset[r0]; // the stretch's candidates are kept from here on
        const std::size_t stretch = static_cast<std::size_t>(b) * stretches_per_block +
                                    static_cast<std::size_t>((r0 - first) / stretch_rows);
        if (refresh) { // every entry, and the candidates written down
          std::uint32_t kept = 0;
          for (std::uint32_t e = offset[r0]; e < offset[r1]; ++e) {
            const auto later = static_cast<std::uint32_t>(neighbour[e] >= last); // a later block
            const std::uint32_t later_mask = 0u - later;
            const std::uint32_t to = (slot & later_mask) | ~later_mask;
            const EntryGap g = test(e, to);
            const double cut = g.reach + near_skin;
            near_entry[base + kept] = e;
            near_slot[base + kept] = to;
            const bool pinned = (kind[g.i] != Kind::free) | (kind[g.j] != Kind::free);
            kept += !(g.dist2 >= cut * cut) | pinned;
            slot += later;
          }
          near_count[stretch] = kept;
        } else { // the candidates only
          const std::uint32_t end = base + near_count[stretch];
          for (std::uint32_t c = base; c < end; ++c) test(near_entry[c], near_slot[c]);
        }
        // second pass: the touching pairs' forces, two at a time (one per lane), added to the
        // particles in entry order (c0 in lane 0, c1 in lane 1); an odd last contact fills both
        for (std::size_t t = 0; t < count; t += 2) {
          const TouchingEntry& c0 = found[t];
          const bool two = t + 1 < count;
          const TouchingEntry& c1 = found[two ? t + 1 : t];
          // the entries' particles, from the list (the stretch's entries are in the L1 cache)
          const auto i0 = static_cast<std::uint32_t>(r0 + row_in_stretch[c0.entry]);
          const auto i1 = static_cast<std::uint32_t>(r0 + row_in_stretch[c1.entry]);
          const std::uint32_t j0 = neighbour[c0.entry], j1 = neighbour[c1.entry];
          const Lanes ri{radius[i0], radius[i1]}, rj{radius[j0], radius[j1]};
          const Lanes dx{c0.d.x, c1.d.x}, dy{c0.d.y, c1.d.y};
          const ContactLanes g = pair_geometry(
              dx, dy, square_root(dx * dx + dy * dy), ri, rj, Lanes{mass[i0], mass[i1]},
              Lanes{mass[j0], mass[j1]}, Lanes{velocity[i0].x, velocity[i1].x},
              Lanes{velocity[i0].y, velocity[i1].y}, Lanes{velocity[j0].x, velocity[j1].x},
              Lanes{velocity[j0].y, velocity[j1].y}, Lanes{spin[i0], spin[i1]},
              Lanes{spin[j0], spin[j1]}, N::uses_r_eff || T::uses_r_eff);
          Lanes spring{history[c0.entry], history[c1.entry]};
          const ForceLanes f =
              one_material ? contact_force<N, T>(uniform, g, spring, dt)
                           : contact_force<N, T>(pair_lanes(pairs(material[i0], material[j0]),
                                                            pairs(material[i1], material[j1])),
                                                 g, spring, dt);
          const auto add = [&](const TouchingEntry& c, std::uint32_t i, std::uint32_t j, int lane) {
            const Vec2 force{f.force_x[lane], f.force_y[lane]};
            history[c.entry] = spring[lane];
            p.force[i] += force;
            p.torque[i] += f.torque_i[lane];
            if (c.slot != no_slot) [[unlikely]] {
              slots[c.slot].force = force;
              slots[c.slot].torque_i = f.torque_i[lane];
              slots[c.slot].torque_j = f.torque_j[lane];
            } else {
              p.force[j] -= force;
              p.torque[j] += f.torque_j[lane];
            }
          };
          add(c0, i0, j0, 0);
          if (two) add(c1, i1, j1, 1);
          const Lanes ratio = g.overlap / smaller(ri, rj);
          worst = std::max(worst, std::max(ratio[0], ratio[1]));
        }
        // every row of the stretch is done: its particles' forces are complete, but for the late
        for (std::ptrdiff_t a = r0; a < r1;) { // runs of rows between late ones
          const std::ptrdiff_t z =
              next_late != list.late.end() && *next_late < r1 ? *next_late : r1;
          if (z > a) {
            const PassReport s =
                done.range(static_cast<std::size_t>(a), static_cast<std::size_t>(z));
            finite = finite && s.finite;
            farthest2 = std::max(farthest2, s.displacement2);
          }
          if (z < r1) ++next_late;
          a = z + 1;
        }
      }
      // the block's time, smoothed over steps (a quarter of the newest): it counts what a count
      // of entries and contacts missed, the correction and prediction of its particles and the
      // memory it waits on
      const auto ns =
          static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                         std::chrono::steady_clock::now() - block_start)
                                         .count());
      std::uint64_t& w = block_work[static_cast<std::size_t>(b)];
      w = w == 0 ? ns + 1 : (3 * w + ns) / 4 + 1;
    }
    // the wall contacts need no pair force: a thread takes them when no block is left to take,
    // while the others finish theirs
    thread_local std::vector<WallHit> hits; // kept from step to step: no allocation in a step
#pragma omp for schedule(dynamic, late_chunk)
    for (std::ptrdiff_t q = 0; q < late; ++q)
      worst = std::max(worst, wall_contacts<N, T>(p, list, walls, pairs, wall_force, dt,
                                                  list.late[static_cast<std::size_t>(q)], hits));
    // every block and wall contact is done (the loop's barrier): the late particles
    const std::ptrdiff_t chunks = (late + late_chunk - 1) / late_chunk;
#pragma omp for schedule(dynamic, 1) nowait
    for (std::ptrdiff_t c = 0; c < chunks; ++c) {
      const auto q0 = static_cast<std::size_t>(c * late_chunk);
      const PassReport s = finish_late(p, list, deferred, wall_force, done, q0,
                                       std::min(q0 + late_chunk, list.late.size()));
      finite = finite && s.finite;
      farthest2 = std::max(farthest2, s.displacement2);
    }
  }
  sum_wall_reactions(list, wall_force, walls);
  return {worst, PassReport{finite, farthest2}};
}

} // namespace

void Simulation::for_each_contact(const std::function<void(const ContactView&)>& f) const {
  const Particles& p = world_.particles;
  ContactView v;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    for (std::uint32_t e = list_.row_offset[i]; e < list_.row_offset[i + 1]; ++e) {
      const std::uint32_t j = list_.neighbour[e];
      const Vec2 d = p.position[i] - (p.position[j] + list_.shift(e, world_.domain));
      const double dist2 = norm2(d), reach = p.radius[i] + p.radius[j];
      if (dist2 >= reach * reach || dist2 == 0.0) continue;
      v.i = i;
      v.j = j;
      v.wall = -1;
      v.geometry =
          pair_geometry(d, std::sqrt(dist2), p.radius[i], p.radius[j], p.mass[i], p.mass[j],
                        p.velocity[i], p.velocity[j], p.angular_velocity[i], p.angular_velocity[j]);
      v.parameters = &pairs_(p.material[i], p.material[j]);
      v.history = list_.history[e];
      f(v);
    }
  }
  std::vector<WallHit> hits;
  for (std::uint32_t i = 0; i < p.size(); ++i)
    for_each_wall_contact(
        p, list_, world_.walls, i, hits,
        [&](std::uint32_t e, const Segment& s, const ContactGeometry& g) {
          v.i = i;
          v.j = i;
          v.wall = static_cast<std::int32_t>(list_.wall_segment[e]);
          v.geometry = g;
          v.parameters = &pairs_(p.material[i], s.material);
          v.history = list_.wall_history[e];
          f(v);
        },
        [](std::uint32_t) {});
}

PassReport Simulation::compute_forces(ForceStageEnd end) {
  Particles& p = world_.particles;
  wall_force_.resize(list_.wall_segment.size());
  deferred_force_.resize(list_.block_first_slot.back());
  const double dt = config_.timestep;
  // The candidates stay valid while two grains cannot have closed their gap: each moved at most
  // drift_bound_ - candidates_base_ (drift_margin kept for rounding). An unknown bound (infinite,
  // or NaN as infinity less infinity) chooses them again at every step.
  const bool refresh = candidates_stale_ || !(2.0 * (drift_bound_ - candidates_base_) <=
                                              drift_margin * candidates_.skin);
  if (refresh) {
    candidates_.skin = ContactCandidates::skin_fraction * list_.skin;
    candidates_base_ = drift_bound_;
    candidates_stale_ = false;
    ++candidate_choices_;
  }
  // the last stage started this one's forces (ForceStageEnd::verlet_correct_predict), or the
  // fused Gear pass did (advance)
  const bool started = forces_started_;
  forces_started_ = false;
  return with_contact_law(config_.normal_law, config_.tangential_law, [&]<class N, class T>() {
    const auto stages = [&](const auto& done) {
      const auto [worst, seam] = force_stage<N, T>(
          p, list_, candidates_, refresh, pairs_, world_.domain, world_.gravity, world_.walls,
          deferred_force_, wall_force_, dt, done, block_work_, block_order_, started, threads_);
      max_overlap_seen_ = worst;
      return seam;
    };
    switch (end) {
    case ForceStageEnd::verlet_correct:
      return stages(VerletCorrect{p, 0.5 * dt});
    case ForceStageEnd::verlet_correct_predict:
      return stages(VerletCorrectPredict{p, dt, 0.5 * dt, world_.gravity});
    case ForceStageEnd::nothing:
      break;
    }
    return stages(NothingMore{});
  });
}

} // namespace talus
