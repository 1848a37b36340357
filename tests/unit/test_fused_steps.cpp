// Simulation::run does one step's correction and the next step's prediction in one pass over
// memory wherever nothing looks at the state between the two (Simulation::advance). That must
// change nothing: the arithmetic is the same, particle by particle, so a run is bit-identical to
// single steps, and every state a caller or an observer sees is a corrected one.
#include <gtest/gtest.h>

#include <vector>

#include "simulation/simulation.hpp"
#include "support/mixed_box.hpp"

namespace talus {
namespace {

using testing::mixed_box;

SimulationConfig config(Integrator integrator, int threads) {
  SimulationConfig c;
  c.timestep = 5.0e-6; // omega dt = 0.12 for the stiffest pair: stable with Gear too
  c.integrator = integrator;
  c.threads = threads;
  c.min_particles_per_thread = 1;
  c.sort_interval = 50;       // renumbered now and then (not on the escape check's steps)
  c.escape_lo = {-1.0, -1.0}; // checked every 16 steps, on the corrected positions
  c.escape_hi = {1.0, 1.0};
  return c;
}

template <class T> void expect_equal(const std::vector<T>& a, const std::vector<T>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a[k], b[k]) << k;
}

// Everything that determines how a run goes on, bit for bit.
void expect_same_state(const Simulation& a, const Simulation& b) {
  EXPECT_EQ(a.step_count(), b.step_count());
  EXPECT_EQ(a.time(), b.time());
  EXPECT_EQ(a.renumberings(), b.renumberings());
  const Particles& p = a.world().particles;
  const Particles& q = b.world().particles;
  expect_equal(p.id, q.id);
  expect_equal(p.position, q.position);
  expect_equal(p.velocity, q.velocity);
  expect_equal(p.angle, q.angle);
  expect_equal(p.angular_velocity, q.angular_velocity);
  expect_equal(p.force, q.force);
  expect_equal(p.torque, q.torque);
  expect_equal(p.force_previous, q.force_previous);
  expect_equal(p.gear.r2, q.gear.r2);
  expect_equal(p.gear.r3, q.gear.r3);
  expect_equal(p.gear.r4, q.gear.r4);
  expect_equal(p.gear.phi4, q.gear.phi4);
  const NeighbourList& l = a.neighbours();
  const NeighbourList& m = b.neighbours();
  EXPECT_EQ(l.builds, m.builds);
  expect_equal(l.neighbour, m.neighbour);
  expect_equal(l.history, m.history);
  expect_equal(l.wall_history, m.wall_history);
  expect_equal(l.reference, m.reference);
}

class FusedSteps : public ::testing::TestWithParam<Integrator> {};

TEST_P(FusedSteps, ARunIsBitIdenticalToSingleSteps) {
  Simulation fused(mixed_box(), config(GetParam(), 2));
  Simulation single(mixed_box(), config(GetParam(), 2));
  fused.run(500);
  for (int k = 0; k < 500; ++k) single.step();
  // the prediction's drift test decided some rebuilds, and renumberings happened in between
  ASSERT_GT(single.neighbours().builds, 3U);
  ASSERT_EQ(single.renumberings(), 10U); // at steps 0, 50, ..., 450
  expect_same_state(fused, single);
}

TEST_P(FusedSteps, AnObserverSeesTheStateOfSingleSteps) {
  Simulation fused(mixed_box(), config(GetParam(), 1));
  Simulation single(mixed_box(), config(GetParam(), 1));
  std::vector<Particles> seen;
  fused.run(
      300, [&](const Simulation& s) { seen.push_back(s.world().particles); }, 7);
  ASSERT_EQ(seen.size(), 42U);
  for (std::size_t k = 1; k <= 300; ++k) {
    single.step();
    if (k % 7 != 0) continue;
    const Particles& p = seen[k / 7 - 1];
    const Particles& q = single.world().particles;
    expect_equal(p.position, q.position);
    expect_equal(p.velocity, q.velocity); // Verlet's predicted velocity would differ
    expect_equal(p.angular_velocity, q.angular_velocity);
  }
  // and the run, resumed by single steps, goes on as the single-stepped one
  for (int k = 0; k < 20; ++k) fused.step(), single.step();
  expect_same_state(fused, single);
}

INSTANTIATE_TEST_SUITE_P(BothIntegrators, FusedSteps,
                         ::testing::Values(Integrator::verlet, Integrator::gear),
                         [](const ::testing::TestParamInfo<Integrator>& param) {
                           return std::string(to_string(param.param));
                         });

} // namespace
} // namespace talus
