// The force stage (two passes per stretch of rows, force blocks with deferred slots) adds every
// touching pair's force once to each partner: compared with a plain loop over the list's entries
// on a packing made to exercise it (periodic images in x and y, long rows, fixed grains, entries
// that cross force blocks).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/random.hpp"
#include "neighbours/neighbour_list.hpp"
#include "scenario/dense2d.hpp"
#include "simulation/block_schedule.hpp"
#include "simulation/simulation.hpp"

namespace talus {
namespace {

World dense_periodic_box(std::uint64_t seed) {
  World w;
  Material m = dense2d_material(); // the benchmark's grains
  m.friction = 0.3;                // low enough for some contacts to slip on the first step
  w.materials = {m};
  w.gravity = {0.0, -9.81};
  const int side = 92; // over 8192 grains: four force blocks (force_block_rows)
  const double pitch = 0.01, length = side * pitch;
  w.domain = {{0.0, 0.0}, {length, length}, true, true};
  RandomStream rng(seed, 1);
  // four large grains between the lattice's sites, each with some fifteen neighbours in its row
  // (the others have about 4), one of them across the periodic corner
  const Vec2 large[] = {{0.1, 0.1}, {0.3, 0.15}, {0.15, 0.3}, {0.0, 0.0}};
  const double large_radius = 0.022;
  for (const Vec2 c : large)
    w.add_particle({.position = c,
                    .radius = large_radius,
                    .velocity = {0.1 * (rng.uniform() - 0.5), 0.1 * (rng.uniform() - 0.5)},
                    .angular_velocity = 10.0 * (rng.uniform() - 0.5)});
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const Vec2 r{pitch * (x + 0.5) + 0.001 * (rng.uniform() - 0.5),
                   pitch * (y + 0.5) + 0.001 * (rng.uniform() - 0.5)};
      bool inside_large = false;
      for (const Vec2 c : large) {
        const Vec2 d = w.domain.minimum_image(r, c);
        inside_large = inside_large || norm(d) < large_radius + 0.001;
      }
      if (inside_large) continue;
      const bool fixed = (x * 7 + y * 3) % 23 == 0;
      w.add_particle({.position = r,
                      .radius = 0.0045 + 0.001 * rng.uniform(), // touching: radii sum > pitch
                      .kind = fixed ? Kind::fixed : Kind::free,
                      .velocity = {0.2 * (rng.uniform() - 0.5), 0.2 * (rng.uniform() - 0.5)},
                      .angular_velocity = 20.0 * (rng.uniform() - 0.5)});
    }
  return w;
}

TEST(ForceStage, AddsEveryTouchingPairOnceToEachPartner) {
  for (const int threads : {1, 2}) {
    SimulationConfig config;
    config.timestep = 1.0e-5;
    config.integrator = Integrator::verlet;
    config.skin = 0.005; // long rows: many entries that do not touch
    config.threads = threads;
    config.min_particles_per_thread = 1;
    // the constructor builds the list (history 0) and computes the forces once
    const Simulation s(dense_periodic_box(7), config);
    const Particles& p = s.world().particles;
    const NeighbourList& l = s.neighbours();
    ASSERT_GT(l.block_first_slot.size(), 4U) << "several force blocks";
    ASSERT_GT(l.block_first_slot.back(), 0U) << "entries that cross a force block";

    const PairTable pairs(s.world().materials, s.config().impact_speed);
    std::vector<Vec2> force(p.size());
    std::vector<double> torque(p.size(), 0.0);
    for (std::size_t k = 0; k < p.size(); ++k)
      force[k] = p.is_free(k) ? p.mass[k] * s.world().gravity : Vec2{};
    std::size_t touching = 0, slipping = 0, images = 0, longest_row = 0;
    for (std::uint32_t i = 0; i < p.size(); ++i) {
      longest_row = std::max<std::size_t>(longest_row, l.row_offset[i + 1] - l.row_offset[i]);
      for (std::uint32_t e = l.row_offset[i]; e < l.row_offset[i + 1]; ++e) {
        const std::uint32_t j = l.neighbour[e];
        const Vec2 shift = l.shift(e, s.world().domain);
        images += shift != Vec2{};
        const Vec2 d = p.position[i] - (p.position[j] + shift);
        const double reach = p.radius[i] + p.radius[j];
        if (norm2(d) >= reach * reach) {
          EXPECT_EQ(l.history[e], 0.0) << "entry " << e << " does not touch";
          continue;
        }
        ++touching;
        const ContactGeometry g =
            pair_geometry(d, norm(d), p.radius[i], p.radius[j], p.mass[i], p.mass[j], p.velocity[i],
                          p.velocity[j], p.angular_velocity[i], p.angular_velocity[j]);
        double history = 0.0;
        const ContactForce c = contact_force<LinearSpringDashpot, CundallStrack>(
            pairs(p.material[i], p.material[j]), g, history, config.timestep);
        slipping += std::abs(history - g.v_tangent * config.timestep) > 0.0;
        // the history of an entry does not depend on the order of the sums: exactly equal
        EXPECT_EQ(l.history[e], history) << "entry " << e;
        force[i] += force_of(c);
        force[j] -= force_of(c);
        torque[i] += c.torque_i;
        torque[j] += c.torque_j;
      }
    }
    ASSERT_GT(longest_row, 12U) << "the large grains' long rows";
    ASSERT_GT(images, 50U) << "entries across the periodic boundaries";
    ASSERT_GT(slipping, 0U);
    ASSERT_GT(touching, p.size() / 2) << "a dense packing: about one touching entry per row";
    // The engine adds a particle's deferred terms after the others, so its sums may differ from
    // this loop's order by rounding: a few units in the last place of the largest term (contact
    // forces here reach about k_n x 2 mm = 200 N, so about 1e-13 N; torques about 1 N m, so
    // about 1e-15 N m). The tolerances, 1e-9 N and 1e-11 N m, are far above that and far below
    // a missing, doubled or altered contact term (a contact with a millionth of a millimetre of
    // overlap already pushes with 1e-4 N).
    for (std::size_t k = 0; k < p.size(); ++k) {
      EXPECT_NEAR(p.force[k].x, force[k].x, 1e-9) << "particle " << k << ", " << threads;
      EXPECT_NEAR(p.force[k].y, force[k].y, 1e-9) << "particle " << k << ", " << threads;
      EXPECT_NEAR(p.torque[k], torque[k], 1e-11) << "particle " << k << ", " << threads;
    }
  }
}

// The order in which the threads take the force blocks: every block once, by decreasing
// measured time, equal times by index (so that nothing measured yet means the list's order).
TEST(ForceBlockOrder, LongestFirstEveryBlockOnce) {
  std::vector<std::ptrdiff_t> order;
  force_block_order(std::vector<std::uint64_t>(4, 0), order);
  EXPECT_EQ(order, (std::vector<std::ptrdiff_t>{0, 1, 2, 3}));
  // a packing denser at the bottom: its first blocks take longer
  force_block_order({10, 12, 5, 10, 7}, order);
  EXPECT_EQ(order, (std::vector<std::ptrdiff_t>{1, 0, 3, 4, 2}));
  // the buffer is resized to the block count, whatever it held
  force_block_order({3}, order);
  EXPECT_EQ(order, (std::vector<std::ptrdiff_t>{0}));
  RandomStream rng(11, 2);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<std::uint64_t> work(16);
    for (auto& w : work) w = static_cast<std::uint64_t>(100.0 * rng.uniform());
    force_block_order(work, order);
    std::vector<std::ptrdiff_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t b = 0; b < sorted.size(); ++b)
      ASSERT_EQ(sorted[b], static_cast<std::ptrdiff_t>(b)) << "every block once";
    for (std::size_t k = 1; k < order.size(); ++k) {
      const std::uint64_t before = work[static_cast<std::size_t>(order[k - 1])],
                          after = work[static_cast<std::size_t>(order[k])];
      ASSERT_GE(before, after);
      if (before == after) {
        ASSERT_LT(order[k - 1], order[k]);
      }
    }
  }
}

} // namespace
} // namespace talus
