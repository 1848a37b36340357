// [[drivers]] of a 3D scenario (scenario/file/load3.hpp, scenario3d/box3.hpp, build3.hpp): the
// box's sides are named, a driver moves the plates its target names and no other, its keys
// resolve and reload, and a target the box has not, a plate driven twice, a key of another
// motion or a motion the 3D engine has not are refused by key. A driven floor and side stand
// where their motion has them after the steps run.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "cli/builtin_scenarios.hpp"
#include "scenario/file/load3.hpp"
#include "scenario3d/box3.hpp"
#include "scenario3d/build3.hpp"

namespace talus {
namespace {

// pour3d (a box open at the top) with 200 spheres and the drivers given
Scenario3 driven(const std::string& drivers, const std::vector<std::string>& set = {}) {
  for (const auto& b : cli::builtin_scenarios())
    if (b.name == "pour3d") {
      std::vector<std::string> with = {"particles.count=200"};
      with.insert(with.end(), set.begin(), set.end());
      return load_scenario3(std::string(b.text) + "\n" + drivers, "driven.toml", with);
    }
  ADD_FAILURE() << "no built-in pour3d";
  return {};
}

std::string refusal(const std::string& drivers, const std::vector<std::string>& set = {}) {
  try {
    driven(drivers, set);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

constexpr const char* shaken_floor = R"([[drivers]]
type = "vibrate"
target = "floor"
amplitude = 1e-3
frequency = 40.0
phase = 0.5
)";

constexpr const char* closing_right = R"([[drivers]]
type = "translate"
target = "right"
velocity = [-0.02, 0.0, 0.0]
)";

TEST(Drivers3, TheBoxSidesAreNamedInThePlatesOrder) {
  Box3Section g;
  std::vector<std::string> names;
  for (const BoxSide& side : box3_sides(g)) names.push_back(side.name);
  EXPECT_EQ(names, (std::vector<std::string>{"left", "right", "front", "back", "floor"}));
  g.open_top = false;
  g.periodic = {true, false, false};
  EXPECT_EQ(box3_targets(g), "walls, front, back, floor, lid");
  EXPECT_EQ(box3_target(g, "walls").size(), 4u);
  EXPECT_EQ(box3_target(g, "lid"), std::vector<std::uint32_t>{3});
  EXPECT_TRUE(box3_target(g, "left").empty());
}

TEST(Drivers3, ADriverMovesThePlatesItsTargetNames) {
  const BuiltScenario3 b = build_scenario3(driven(std::string(shaken_floor) + closing_right));
  ASSERT_EQ(b.scene.drivers.size(), 2u);
  const PlateDriver& floor = b.scene.drivers[0];
  EXPECT_EQ(floor.plate, 4u);
  EXPECT_EQ(floor.motion, PlateDriver::Motion::vibrate);
  EXPECT_EQ(floor.amplitude, 1e-3);
  EXPECT_EQ(floor.phase, 0.5);
  EXPECT_EQ(floor.direction.z, 1.0); // the default: along z
  EXPECT_EQ(b.scene.drivers[1].plate, 1u);
  EXPECT_EQ(b.scene.drivers[1].velocity.x, -0.02);
  const BuiltScenario3 all =
      build_scenario3(driven("[[drivers]]\ntype = 'rotate'\ncentre = [0.015, 0.015, 0]\n"
                             "angular_velocity = [0, 0, 0.5]\n"));
  ASSERT_EQ(all.scene.drivers.size(), 5u); // "walls", the default target: every plate
  for (std::uint32_t w = 0; w < 5; ++w) {
    EXPECT_EQ(all.scene.drivers[w].plate, w);
    EXPECT_EQ(all.scene.drivers[w].pivot.x, 0.015);
    EXPECT_EQ(all.scene.drivers[w].angular_velocity.z, 0.5);
  }
}

TEST(Drivers3, DriversResolveAndReloadToTheSameText) {
  const Scenario3 s = driven(std::string(shaken_floor) + closing_right);
  const std::string resolved = to_toml(s);
  EXPECT_NE(resolved.find("target = 'right'"), std::string::npos) << resolved;
  EXPECT_EQ(resolved.find("angular_velocity = [ 0.0"), std::string::npos)
      << "a translation's driver wrote a rotation's keys:\n"
      << resolved;
  const Scenario3 again = load_scenario3(resolved, "resolved");
  ASSERT_EQ(again.drivers.size(), 2u);
  EXPECT_EQ(again.drivers[0].frequency, 40.0);
  EXPECT_EQ(to_toml(again), resolved);
}

TEST(Drivers3, WhatADriverCannotDoIsRefusedByKey) {
  const auto says = [](const std::string& drivers, const std::string& words,
                       const std::vector<std::string>& set = {}) {
    const std::string e = refusal(drivers, set);
    EXPECT_NE(e.find(words), std::string::npos) << drivers << ": " << e;
  };
  says("[[drivers]]\ntype = 'translate'\ntarget = 'lid'\n",
       "'drivers.0.target': 'lid' is not a plate of this box; allowed: walls, left, right, front, "
       "back, floor");
  says("[[drivers]]\ntype = 'translate'\ntarget = 'left'\n", "allowed: walls, front, back, floor",
       {"geometry.periodic=x"});
  says(std::string(shaken_floor) + "[[drivers]]\ntype = 'translate'\n",
       "'drivers.1.target': the floor is moved by drivers.0 already");
  says("[[drivers]]\ntype = 'cell'\nshear_rate = 1.0\n",
       "'drivers.0.type': a deforming cell needs a box with no plates");
  says("[[drivers]]\ntype = 'shake'\n", "'shake' is not one of the allowed values");
  says("[[drivers]]\ntype = 'translate'\namplitude = 1e-3\n",
       "'drivers.0.amplitude': only a vibrate driver has it (this one is translate)");
  says("[[drivers]]\ntype = 'vibrate'\nangular_velocity = [0, 0, 1]\n",
       "only a rotate driver has it");
  says("[[drivers]]\ntype = 'vibrate'\ndirection = [0, 0, 0]\n", "must not be zero");
  says("[[drivers]]\ntype = 'translate'\nvelocity = [1, 0]\n", "expected [x, y, z]");
  says("[[drivers]]\ntype = 'vibrate'\nfrequency = -1\n", "'drivers.0.frequency'");
  says("[[drivers]]\ntype = 'translate'\nspeed = 1\n", "'drivers.0.speed'");
}

// The plates stand where the motion has them at the step's time, to rounding: the driven floor
// A sin(2 pi f t + phase) off where it started (from its first step: a phase shifts it at once),
// the right side v t in from x1.
TEST(Drivers3, DrivenPlatesStandWhereTheirMotionHasThem) {
  const Scenario3 s = driven(std::string(shaken_floor) + closing_right);
  const BuiltScenario3 b = build_scenario3(s);
  Simulation3 sim(b.scene, b.settings);
  for (int k = 0; k < 400; ++k) sim.step();
  const double t = 400.0 * b.settings.timestep;
  const Plane& floor = sim.scene().plates[4];
  const Plane& right = sim.scene().plates[1];
  const double w = 2.0 * std::numbers::pi * 40.0;
  EXPECT_NEAR(floor.centre.z, 1e-3 * std::sin(w * t + 0.5), 1e-15);
  EXPECT_NEAR(floor.velocity.z, 1e-3 * w * std::cos(w * t + 0.5), 1e-12);
  EXPECT_NEAR(right.centre.x, s.geometry.hi.x - 0.02 * t, 1e-15);
  EXPECT_EQ(sim.scene().plates[0].centre.x, 0.0); // the left side stays
}

} // namespace
} // namespace talus
