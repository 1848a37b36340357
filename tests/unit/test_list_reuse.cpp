// The neighbour list is tested against the grains' build positions only when a bound on their
// drift says it could be stale, and the force stage tests only the entries that can touch before
// the grains move on (ContactCandidates). Both are shortcuts, never approximations: a run must be
// bit-identical to one that tests every entry and every position at every step, which
// Simulation::edit_world forces (it makes the drift bound unknown). And what the integrator does
// not move (held grains, driven grains, a caller's edit) must still be seen.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "scenario/dense2d.hpp"
#include "simulation/simulation.hpp"
#include "support/mixed_box.hpp"
#include "support/same_state.hpp"

namespace talus {
namespace {

using testing::expect_same_state;
using testing::mixed_box;

SimulationConfig config(Integrator integrator) {
  SimulationConfig c;
  c.timestep = 5.0e-6; // omega dt = 0.12 for the stiffest pair: stable with Gear too
  c.integrator = integrator;
  c.threads = 2;
  c.min_particles_per_thread = 1;
  c.sort_interval = 100;
  return c;
}

class ListReuse : public ::testing::TestWithParam<Integrator> {};

TEST_P(ListReuse, RunsAreBitIdenticalToTestingEverythingEveryStep) {
  Simulation reusing(mixed_box(), config(GetParam()));
  Simulation testing_all(mixed_box(), config(GetParam()));
  for (int k = 0; k < 600; ++k) {
    reusing.step();
    testing_all.edit_world(); // the drift bound unknown: every position and entry tested
    testing_all.step();
  }
  // the shortcuts were taken, and not only taken: rebuilds were needed in between
  EXPECT_GT(reusing.neighbours().builds, 3U);
  EXPECT_LT(reusing.drift_tests(), 300U);
  EXPECT_LT(reusing.candidate_choices(), 300U);
  EXPECT_EQ(testing_all.candidate_choices(), 601U); // the constructor's stage and every step's
  // the same rebuilds (compared in expect_same_state) and the same contacts, bit for bit
  expect_same_state(reusing, testing_all);
  // and run() (fused steps) takes the same shortcuts
  Simulation fused(mixed_box(), config(GetParam()));
  fused.run(600);
  expect_same_state(fused, testing_all);
}

// A restored run (a checkpoint resumed, a benchmark's round) and a run after an edit start with
// the drift bound unknown: the first step compares the positions with the build's and takes the
// farthest move as the bound, so the shortcuts are taken again from then on, not only after the
// next build. Bit-identical still to testing everything at every step.
TEST_P(ListReuse, ARestoredRunTakesTheShortcutsBeforeTheNextBuild) {
  Simulation settling(mixed_box(), config(GetParam()));
  settling.run(300);
  const SimulationState state = settling.state();
  Simulation restored = Simulation::restore(state, settling.config());
  Simulation testing_all = Simulation::restore(state, settling.config());
  const std::uint64_t builds = restored.neighbours().builds;
  int steps = 0; // until the next build
  for (; steps < 200 && restored.neighbours().builds == builds; ++steps) {
    restored.step();
    testing_all.edit_world();
    testing_all.step();
  }
  // an unknown bound would choose the candidates and compare the positions at every step
  ASSERT_GE(steps, 20);
  EXPECT_LE(restored.candidate_choices(), static_cast<std::uint64_t>(steps / 4));
  EXPECT_LT(restored.drift_tests(), static_cast<std::uint64_t>(steps / 2));
  expect_same_state(restored, testing_all);
}

INSTANTIATE_TEST_SUITE_P(BothIntegrators, ListReuse,
                         ::testing::Values(Integrator::verlet, Integrator::gear),
                         [](const ::testing::TestParamInfo<Integrator>& param) {
                           return std::string(to_string(param.param));
                         });

// The drift bound adds up what each pass over the particles reports as its largest displacement:
// it must be how far that pass moved the farthest free grain (to rounding: 1e-15 m, a few units
// in the last place of coordinates of 0.4 m).
double farthest(const Particles& before, const Particles& after) {
  double d2 = 0.0;
  for (std::size_t i = 0; i < after.size(); ++i)
    if (after.is_free(i)) d2 = std::max(d2, norm2(after.position[i] - before.position[i]));
  return std::sqrt(d2);
}

TEST(ListReuse, EveryPassReportsHowFarItMovedTheFarthestGrain) {
  constexpr double rounding = 1e-15; // m
  for (const Integrator integrator : {Integrator::verlet, Integrator::gear}) {
    Simulation s(mixed_box(), config(integrator));
    s.run(50);
    const Particles start = s.world().particles;
    const double dt = s.config().timestep;
    Particles p = start;
    if (integrator == Integrator::verlet) {
      const double moved = std::sqrt(verlet_predict(p, dt, 1, 1.0));
      EXPECT_GT(moved, 1e-8);
      EXPECT_NEAR(moved, farthest(start, p), rounding);
      continue;
    }
    const double predicted = std::sqrt(gear_predict(p, dt, 1));
    EXPECT_GT(predicted, 1e-8);
    EXPECT_NEAR(predicted, farthest(start, p), rounding);
    const Particles before_correction = p; // corrected with the forces of the start, off by dt
    const PassReport corrected = gear_correct(p, dt, 1);
    EXPECT_GT(std::sqrt(corrected.displacement2), 1e-12);
    EXPECT_NEAR(std::sqrt(corrected.displacement2), farthest(before_correction, p), rounding);
    Particles q = before_correction;
    const PassReport both = gear_correct_predict(q, dt, s.world().gravity, 1);
    EXPECT_NEAR(std::sqrt(both.displacement2), farthest(before_correction, q), rounding);
  }
}

// Two grains of radius 5 mm, no gravity, a fixed skin of 1 mm: `gap` between them along x.
World two_grains(double gap, Kind first = Kind::free) {
  World w;
  w.materials = {dense2d_material()};
  w.gravity = {0.0, 0.0};
  w.domain = {{-1.0, -1.0}, {1.0, 1.0}, false, false};
  w.add_particle({.position = {0.0, 0.0}, .radius = 0.005, .kind = first});
  w.add_particle({.position = {0.01 + gap, 0.0}, .radius = 0.005});
  return w;
}

SimulationConfig fixed_skin(Integrator integrator = Integrator::verlet) {
  SimulationConfig c;
  c.timestep = 5.0e-6;
  c.integrator = integrator;
  c.threads = 1;
  c.skin = 1.0e-3; // candidates: gaps below 0.2 mm
  return c;
}

// A held grain is moved by displace_held, not by the integrator: the drift bound does not see it,
// so its entries must be candidates whatever their gap.
TEST(ListReuse, AHeldGrainPushedIntoANeighbourTouchesIt) {
  Simulation s(two_grains(0.3e-3), fixed_skin()); // in the list, not a candidate by its gap
  s.step();
  s.edit_particles().hold(0, true);
  const std::uint64_t builds = s.neighbours().builds;
  for (int k = 0; k < 4; ++k) { // 0.4 mm in all: 0.1 mm of overlap, less than half the skin
    s.edit_particles().displace_held(0, {0.1e-3, 0.0});
    s.step();
  }
  EXPECT_EQ(s.neighbours().builds, builds); // the list was not rebuilt: the candidates saw it
  EXPECT_GT(s.world().particles.force[1].x, 0.0);
}

// A driven grain is moved by its driver: the same. (With Gear, which does not predict driven
// grains; velocity Verlet's prediction moves them by their velocity before the driver does.)
TEST(ListReuse, ADrivenGrainPushedIntoANeighbourTouchesIt) {
  World w = two_grains(0.3e-3, Kind::moved);
  Driver d;
  d.motion = Translate{{0.1, 0.0}}; // 0.35 mm in 700 steps: 0.05 mm of overlap
  d.targets.particles = {0};
  attach(d, w);
  w.drivers.push_back(d);
  Simulation s(std::move(w), fixed_skin(Integrator::gear));
  const std::uint64_t builds = s.neighbours().builds;
  s.run(700);
  EXPECT_EQ(s.neighbours().builds, builds);
  EXPECT_GT(s.world().particles.velocity[1].x, 0.0);
}

// A grain a caller moves between steps (edit_world) is seen at the next step, however far it
// went, although the drift bound of the grains at rest is zero.
TEST(ListReuse, AGrainMovedThroughEditWorldIsSeen) {
  Simulation s(two_grains(0.04), fixed_skin()); // 40 mm apart: not in the list
  s.run(10);
  ASSERT_EQ(s.neighbours().pair_count(), 0U);
  s.edit_world().particles.position[0] = {0.04 + 0.1e-3, 0.0}; // 0.1 mm of overlap
  s.step();
  EXPECT_GT(s.world().particles.force[1].x, 0.0);
}

} // namespace
} // namespace talus
