// Renumbering the particles (Simulation::sort_particles, SimulationConfig::sort_interval) keeps
// the physical state: every particle by id, every pair of the neighbour list with its history,
// every force to rounding, and the drivers' targets.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include "simulation/simulation.hpp"
#include "support/mixed_box.hpp"
#include "support/pairs_by_id.hpp"

namespace talus {
namespace {

using testing::mixed_box;

SimulationConfig config(int threads, std::uint64_t sort_interval) {
  SimulationConfig c;
  c.timestep = 1.0e-5;
  c.integrator = Integrator::verlet;
  c.threads = threads;
  c.min_particles_per_thread = 1;
  c.sort_interval = sort_interval;
  return c;
}

// index_of_id(p)[id]: where particle `id` is now
std::vector<std::uint32_t> index_of_id(const Particles& p) {
  std::vector<std::uint32_t> at(p.size());
  for (std::uint32_t k = 0; k < p.size(); ++k) at[p.id[k]] = k;
  return at;
}

// The same particles in the same order, at bit-identical positions and `field`.
template <class T>
void expect_identical(const Particles& a, const Particles& b, std::vector<T> Particles::*field) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a.id[k], b.id[k]);
    EXPECT_EQ(a.position[k], b.position[k]) << k;
    EXPECT_EQ((a.*field)[k], (b.*field)[k]) << k;
  }
}

using testing::PairKey;

std::map<PairKey, double> pairs_by_id(const Simulation& s) {
  const NeighbourList& l = s.neighbours();
  std::map<PairKey, double> out;
  testing::for_each_pair_by_id(
      s, [&](const PairKey& key, std::uint32_t e, bool) { out[key] = l.history[e]; });
  return out;
}

TEST(SortParticles, KeepsEveryParticlePairAndForce) {
  Simulation s(mixed_box(), config(1, 0));
  s.run(200); // contacts with history
  const Particles before = s.world().particles;
  const auto pairs_before = pairs_by_id(s);
  std::size_t with_history = 0;
  for (const auto& [key, h] : pairs_before) with_history += h != 0.0;
  ASSERT_GT(with_history, 100U);
  std::size_t across = 0; // entries across the periodic boundary
  for (const ImageShift m : s.neighbours().image) across += m.sx != 0;
  ASSERT_GT(across, 10U);

  s.sort_particles();
  ASSERT_EQ(s.renumberings(), 1U);
  const Particles& after = s.world().particles;
  ASSERT_EQ(after.size(), before.size());
  // every particle by id, exactly
  const std::vector<std::uint32_t> old_index = index_of_id(before);
  for (std::size_t k = 0; k < after.size(); ++k) {
    const std::uint32_t old = old_index[after.id[k]];
    EXPECT_EQ(s.new_indices()[old], k);
    EXPECT_EQ(after.position[k], before.position[old]);
    EXPECT_EQ(after.velocity[k], before.velocity[old]);
    EXPECT_EQ(after.angular_velocity[k], before.angular_velocity[old]);
    EXPECT_EQ(after.radius[k], before.radius[old]);
    EXPECT_EQ(after.kind[k], before.kind[old]);
  }
  // the order follows space: cells row by row, so y rises (by at most a cell) along the order
  double highest = 0.0;
  for (std::size_t k = 0; k < after.size(); ++k) {
    EXPECT_GT(after.position[k].y, highest - 0.021) << k;
    highest = std::max(highest, after.position[k].y);
  }
  // the same pairs with the same history, each at its right periodic image: within reach and
  // skin, as at its build (grains have moved by less than half the skin since)
  EXPECT_EQ(pairs_by_id(s), pairs_before);
  const NeighbourList& l = s.neighbours();
  for (std::uint32_t i = 0; i < after.size(); ++i)
    for (std::uint32_t e = l.row_offset[i]; e < l.row_offset[i + 1]; ++e) {
      const std::uint32_t j = l.neighbour[e];
      EXPECT_GT(j, i) << "a half list";
      const Vec2 d = after.position[i] - (after.position[j] + l.shift(e, s.world().domain));
      EXPECT_LT(norm(d), after.radius[i] + after.radius[j] + 2.0 * l.skin) << "entry " << e;
    }
  // the drivers move the same grains
  for (const std::uint32_t i : s.world().drivers[0].targets.particles)
    EXPECT_EQ(after.kind[i], Kind::moved);

  // the next step from the sorted state and from the unsorted one agree to rounding
  Simulation u(mixed_box(), config(1, 0));
  u.run(201);
  s.step();
  const Particles& a = s.world().particles;
  const Particles& b = u.world().particles;
  const std::vector<std::uint32_t> in_b = index_of_id(b);
  for (std::size_t k = 0; k < a.size(); ++k) {
    const std::uint32_t j = in_b[a.id[k]];
    // forces of about 1 N summed in another order: differences of a few 1e-16 N, far below
    // a missing or doubled contact (1e-4 N for a micrometre of overlap)
    EXPECT_NEAR(a.force[k].x, b.force[j].x, 1e-9) << "id " << a.id[k];
    EXPECT_NEAR(a.force[k].y, b.force[j].y, 1e-9) << "id " << a.id[k];
    EXPECT_NEAR(a.torque[k], b.torque[j], 1e-11) << "id " << a.id[k];
    EXPECT_NEAR(a.position[k].x, b.position[j].x, 1e-15);
  }
}

TEST(SortParticles, EveryIntervalAndTheSameOnOneAndTwoThreads) {
  Simulation one(mixed_box(), config(1, 50)), two(mixed_box(), config(2, 50));
  one.run(300);
  two.run(300);
  EXPECT_EQ(one.renumberings(), 6U); // at steps 0, 50, ..., 250
  ASSERT_EQ(two.renumberings(), one.renumberings());
  expect_identical(one.world().particles, two.world().particles, &Particles::velocity);
}

TEST(SortParticles, AResumedRunRenumbersAsTheUninterruptedOne) {
  Simulation whole(mixed_box(), config(1, 50));
  whole.run(300);
  Simulation first(mixed_box(), config(1, 50));
  first.run(150); // a checkpoint at a step where the next one renumbers
  Simulation rest = Simulation::restore(first.state(), config(2, 50));
  rest.run(150);
  expect_identical(whole.world().particles, rest.world().particles, &Particles::angular_velocity);
}

} // namespace
} // namespace talus
