// The native engine's rolling resistance (simulation/rolling_pass.hpp): its springs follow the
// pairs through list builds, renumberings (where a pair's first grain changes, the angle seen
// from it changes sign), threads, checkpoints and fused steps, as the tangential springs do.
#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "io/checkpoint.hpp"
#include "simulation/simulation.hpp"
#include "support/mixed_box.hpp"
#include "support/pairs_by_id.hpp"
#include "support/same_state.hpp"

namespace talus {
namespace {

using testing::expect_same_state;

World rolling_box() {
  World w = testing::mixed_box();
  w.materials[0].rolling_friction = 0.3;
  return w;
}

SimulationConfig rolling_config(Integrator integrator, int threads,
                                std::uint64_t sort_interval = 50) {
  SimulationConfig c;
  c.timestep = 5.0e-6;
  c.integrator = integrator;
  c.threads = threads;
  c.min_particles_per_thread = 1;
  c.sort_interval = sort_interval;
  c.tangential_law = law_id<CundallStrack>;
  return c;
}

class RollingPass : public ::testing::TestWithParam<Integrator> {};

TEST_P(RollingPass, OneAndTwoThreadsGiveTheSameBits) {
  Simulation one(rolling_box(), rolling_config(GetParam(), 1)),
      two(rolling_box(), rolling_config(GetParam(), 2));
  one.run(300);
  two.run(300);
  std::size_t held = 0;
  for (const double theta : one.neighbours().rolling) held += theta != 0.0;
  ASSERT_GT(held, 100U); // springs in play
  ASSERT_GE(one.renumberings(), 5U);
  expect_same_state(one, two);
}

TEST_P(RollingPass, AResumedRunIsTheUninterruptedOne) {
  Simulation whole(rolling_box(), rolling_config(GetParam(), 1));
  whole.run(300);
  Simulation first(rolling_box(), rolling_config(GetParam(), 1));
  first.run(130);
  // through a checkpoint's bytes
  const Checkpoint saved =
      decode_checkpoint(encode_checkpoint({first.state(), first.config(), ""}), "test");
  Simulation rest = Simulation::restore(saved.state, saved.config);
  rest.run(170);
  // (a restored simulation counts its renumberings from 0)
  EXPECT_EQ(first.renumberings() + rest.renumberings(), whole.renumberings());
  const Particles& p = whole.world().particles;
  const Particles& q = rest.world().particles;
  testing::expect_equal(p.position, q.position);
  testing::expect_equal(p.velocity, q.velocity);
  testing::expect_equal(p.angular_velocity, q.angular_velocity);
  testing::expect_equal(p.torque, q.torque);
  testing::expect_equal(whole.neighbours().rolling, rest.neighbours().rolling);
  testing::expect_equal(whole.neighbours().wall_rolling, rest.neighbours().wall_rolling);
}

TEST_P(RollingPass, SingleStepsAreTheRunsSteps) {
  Simulation run(rolling_box(), rolling_config(GetParam(), 2)),
      single(rolling_box(), rolling_config(GetParam(), 2));
  run.run(200);
  for (int k = 0; k < 200; ++k) single.step();
  expect_same_state(run, single);
}

INSTANTIATE_TEST_SUITE_P(BothIntegrators, RollingPass,
                         ::testing::Values(Integrator::verlet, Integrator::gear),
                         [](const ::testing::TestParamInfo<Integrator>& param) {
                           return std::string(to_string(param.param));
                         });

using testing::PairKey;

// Each pair's rolling angle seen from its grain of the smaller id.
std::map<PairKey, double> angles_by_id(const Simulation& s) {
  const NeighbourList& l = s.neighbours();
  std::map<PairKey, double> out;
  testing::for_each_pair_by_id(s, [&](const PairKey& key, std::uint32_t e, bool from_smaller) {
    out[key] = from_smaller ? l.rolling[e] : -l.rolling[e];
  });
  return out;
}

TEST(RollingPass, ARenumberingTurnsTheAngleWithItsPair) {
  Simulation s(rolling_box(), rolling_config(Integrator::verlet, 1, 0));
  s.run(200);
  const auto before = angles_by_id(s);
  s.sort_particles();
  EXPECT_EQ(angles_by_id(s), before);
  // and some pairs did turn: their first grain changed
  std::size_t turned = 0;
  const Particles& p = s.world().particles;
  const NeighbourList& l = s.neighbours();
  for (std::uint32_t i = 0; i < p.size(); ++i)
    for (std::uint32_t e = l.row_offset[i]; e < l.row_offset[i + 1]; ++e)
      turned += l.rolling[e] != 0.0 && p.id[i] > p.id[l.neighbour[e]];
  EXPECT_GT(turned, 10U);
}

} // namespace
} // namespace talus
