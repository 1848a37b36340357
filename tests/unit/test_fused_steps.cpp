// Simulation::run does one step's correction and the next step's prediction in one pass over
// memory wherever nothing looks at the state between the two (Simulation::advance). That must
// change nothing: the arithmetic is the same, particle by particle, so a run is bit-identical to
// single steps, and every state a caller or an observer sees is a corrected one.
#include <gtest/gtest.h>

#include <vector>

#include "simulation/simulation.hpp"
#include "support/mixed_box.hpp"
#include "support/same_state.hpp"

namespace talus {
namespace {

using testing::expect_equal;
using testing::expect_same_state;
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

class FusedSteps : public ::testing::TestWithParam<Integrator> {};

TEST_P(FusedSteps, ARunIsBitIdenticalToSingleSteps) {
  Simulation fused(mixed_box(), config(GetParam(), 2));
  Simulation single(mixed_box(), config(GetParam(), 2));
  fused.run(500);
  for (int k = 0; k < 500; ++k) single.step();
  // the prediction's drift test decided some rebuilds, and renumberings happened in between
  ASSERT_GE(single.neighbours().builds, 3U); // the constructor's, and two or more of the test's
  ASSERT_EQ(single.renumberings(), 10U);     // at steps 0, 50, ..., 450
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
