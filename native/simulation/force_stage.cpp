// The force stage, block by block of rows: every sum has an order fixed by the list alone, so the
// result does not depend on the number of threads, and no floating-point atomics are needed.
#include "simulation/force_stage.hpp"

#include <algorithm>
#include <vector>

#include <omp.h>

#include "simulation/late_pass.hpp"
#include "simulation/pair_pass.hpp"
#include "simulation/particle_finish.hpp"
#include "simulation/wall_pass.hpp"

namespace talus {

PassReport ForceStage::compute(World& world, NeighbourList& list, const PairTable& pairs,
                               Finish finish, double drift_bound, int threads,
                               const StepFeatures& features) {
  wall_force_.resize(list.wall_segment.size());
  deferred_.resize(list.block_first_slot.back());
  // The candidates stay valid while two grains cannot have closed their gap: each moved at most
  // drift_bound - candidates_base_ (drift_margin kept for rounding). An unknown bound (infinite,
  // or NaN as infinity less infinity) chooses them again at every stage.
  const bool refresh = candidates_stale_ ||
                       !(2.0 * (drift_bound - candidates_base_) <= drift_margin * candidates_.skin);
  if (refresh) {
    candidates_.skin = ContactCandidates::skin_fraction * list.skin;
    candidates_base_ = drift_bound;
    candidates_stale_ = false;
    ++candidate_choices_;
  }
  Particles& p = world.particles;
  const double dt = dt_;
  // the shapes of the finishes that never add the weight are compiled with gravity only
  return with_contact_law(normal_, tangential_, [&]<class N, class T>() {
    switch (finish) {
    case Finish::verlet_correct:
      return with_step_shape<T, false>(features, [&]<class S>() {
        return run<N, T, S>(world, list, pairs, refresh,
                            VerletCorrect<S::rotation>{p, 0.5 * dt, verlet_lag_}, threads,
                            features);
      });
    case Finish::verlet_correct_predict:
      return with_step_shape<T>(features, [&]<class S>() {
        return run<N, T, S>(world, list, pairs, refresh,
                            VerletCorrectPredict<S::rotation, S::gravity>{
                                p, dt, 0.5 * dt, verlet_lag_, world.gravity},
                            threads, features);
      });
    case Finish::nothing:
      break;
    }
    return with_step_shape<T, false>(features, [&]<class S>() {
      return run<N, T, S>(world, list, pairs, refresh, NothingMore{}, threads, features);
    });
  });
}

// Forces between particles, block by block (NeighbourList: force blocks), in the order of the
// schedule (block_schedule.hpp): a block writes only its own particles, so blocks run side by
// side. A thread that finds no block left takes wall contacts, which need no pair force, while the
// others finish theirs; once every block and wall contact is done (the loop's barrier), the late
// particles get their deferred and wall forces (late_pass.hpp), in the same parallel region.
// `done.range(first, last)` is called for particles whose forces are complete; its answers are
// merged.
template <class N, class T, class S, class Done>
PassReport ForceStage::run(World& world, NeighbourList& list, const PairTable& pairs, bool refresh,
                           const Done& done, int threads, const StepFeatures& features) {
  Particles& p = world.particles;
  const auto blocks = static_cast<std::ptrdiff_t>(list.block_first_slot.size()) - 1;
  if (refresh) {
    const auto rows = static_cast<std::ptrdiff_t>(list.block_rows);
    const auto stretches = static_cast<std::size_t>((rows + stretch_rows - 1) / stretch_rows);
    candidates_.entry.resize(list.pair_count());
    candidates_.slot.resize(list.pair_count());
    candidates_.count.resize(static_cast<std::size_t>(blocks) * stretches);
  }
  const bool started = forces_started_;
  forces_started_ = false;
  const PairLaneSource lanes(pairs, S::one_material, features.material);
  const PairParameters& uniform = pairs(features.material, features.material);
  // without walls no particle has a wall row: the pass over the late particles for them is left
  // out
  const auto walled = static_cast<std::ptrdiff_t>(features.walls ? list.late.size() : 0);
  schedule_.plan(static_cast<std::size_t>(blocks));
  const auto late = static_cast<std::ptrdiff_t>(list.late.size());
  double worst = 0.0, farthest2 = 0.0;
  bool finite = true;
#pragma omp parallel num_threads(threads) reduction(max : worst, farthest2) reduction(&& : finite)
  {
    BlockArrays a(p, list, deferred_.data(), world.domain.size());
    PassReport report{true, 0.0};
#pragma omp for schedule(dynamic, 1) nowait
    for (std::ptrdiff_t taken = 0; taken < blocks; ++taken) {
      const std::ptrdiff_t b = schedule_.block(taken);
      const auto start = BlockSchedule::Clock::now();
      worst = std::max(
          worst, block<N, T, S>(a, list, lanes, b, refresh, started, world.gravity, done, report));
      schedule_.record(b, start);
    }
    thread_local std::vector<WallHit> hits; // kept from step to step: no allocation in a step
#pragma omp for schedule(dynamic, late_chunk)
    for (std::ptrdiff_t q = 0; q < walled; ++q)
      worst = std::max(worst, wall_contacts<N, T, S>(p, list, world.walls, pairs, uniform,
                                                     wall_force_, dt_, share_,
                                                     list.late[static_cast<std::size_t>(q)], hits));
    const std::ptrdiff_t chunks = (late + late_chunk - 1) / late_chunk;
#pragma omp for schedule(dynamic, 1) nowait
    for (std::ptrdiff_t c = 0; c < chunks; ++c) {
      const auto q0 = static_cast<std::size_t>(c * late_chunk);
      const PassReport z = finish_late<S::rotation>(p, list, deferred_, wall_force_, done, q0,
                                                    std::min(q0 + late_chunk, list.late.size()));
      report.finite = report.finite && z.finite;
      report.displacement2 = std::max(report.displacement2, z.displacement2);
    }
    finite = finite && report.finite;
    farthest2 = std::max(farthest2, report.displacement2);
  }
  sum_wall_reactions(list, wall_force_, world.walls);
  deepest_overlap_ = worst;
  return {finite, farthest2};
}

// A block's rows go by stretches of stretch_rows, in two passes: the touch test
// (contact_candidates.hpp) writes down the touching entries, then the pair pass (pair_pass.hpp)
// computes their forces. The sums are the same, in the same order, as in one pass that tests
// every entry and branches. Once a stretch's rows are done, the forces of its particles are
// complete (rows after them never name them), but for the late ones (NeighbourList::late): they
// are done by runs between late ones.
template <class N, class T, class S, class Done>
double ForceStage::block(BlockArrays& a, const NeighbourList& list, const PairLaneSource& pairs,
                         std::ptrdiff_t b, bool refresh, bool started, Vec2 gravity,
                         const Done& done, PassReport& report) {
  // per thread, kept from step to step: it grows only when a stretch has more entries than any
  // before it, so steps after the first few allocate nothing
  thread_local std::vector<TouchingEntry> touching;
  const auto rows = static_cast<std::ptrdiff_t>(list.block_rows);
  const auto n = static_cast<std::ptrdiff_t>(a.p.size());
  const std::ptrdiff_t first = b * rows, last = std::min(n, first + rows);
  if (!started) // else the fused pass before this stage started them
    for (std::ptrdiff_t k = first; k < last; ++k)
      start_forces<true, S::rotation>(a.p, k, gravity, a.p.force.data(), a.p.torque.data());
  std::uint32_t slot = list.block_first_slot[b];
  // a deferred entry that does not touch leaves a zero in its slot
  std::fill(a.slots + slot, a.slots + list.block_first_slot[b + 1], PairForce{});
  // the block's late particles, walked alongside the rows (no per-row lookup)
  auto next_late = std::lower_bound(list.late.begin(), list.late.end(), first);
  const std::size_t first_stretch =
      static_cast<std::size_t>(b) *
      static_cast<std::size_t>((rows + stretch_rows - 1) / stretch_rows);
  double worst = 0.0;
  for (std::ptrdiff_t r0 = first; r0 < last; r0 += stretch_rows) {
    const std::ptrdiff_t r1 = std::min(last, r0 + stretch_rows);
    if (touching.size() < a.offset[r1] - a.offset[r0]) touching.resize(a.offset[r1] - a.offset[r0]);
    std::uint32_t& kept =
        candidates_.count[first_stretch + static_cast<std::size_t>((r0 - first) / stretch_rows)];
    const std::size_t count =
        refresh ? touching_choosing_candidates<S::history>(a, candidates_, r0, r1, last, slot, kept,
                                                           touching.data())
                : touching_candidates<S::history>(a, candidates_, r0, kept, touching.data());
    worst =
        std::max(worst, pair_forces<N, T, S>(a, pairs, touching.data(), count, r0, dt_, share_));
    for (std::ptrdiff_t k = r0; k < r1;) { // runs of rows between late ones
      const std::ptrdiff_t z = next_late != list.late.end() && *next_late < r1 ? *next_late : r1;
      if (z > k) {
        const PassReport d = done.range(static_cast<std::size_t>(k), static_cast<std::size_t>(z));
        report.finite = report.finite && d.finite;
        report.displacement2 = std::max(report.displacement2, d.displacement2);
      }
      if (z < r1) ++next_late;
      k = z + 1;
    }
  }
  return worst;
}

namespace {
template <class V> std::size_t bytes(const std::vector<V>& v) {
  return v.capacity() * sizeof(V);
}
} // namespace

std::size_t ForceStage::candidate_bytes() const {
  return bytes(candidates_.entry) + bytes(candidates_.slot) + bytes(candidates_.count);
}

std::size_t ForceStage::footprint_bytes() const {
  return bytes(deferred_) + bytes(wall_force_) + schedule_.footprint_bytes();
}

} // namespace talus
