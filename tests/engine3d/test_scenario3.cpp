// Scenario files of spheres in 3D (scenario/file/load3.hpp, scenario3d/build3.hpp): the built-in
// pour3d loads and its resolved form reloads to the same text; what the 3D engine does not have
// is refused naming the key; the build puts the spheres in the box, as the seed says, and
// refuses a count the box cannot hold or a timestep too long for the collisions.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/builtin_scenarios.hpp"
#include "scenario/file/load.hpp"
#include "scenario/file/load3.hpp"
#include "scenario/file/shared_sections.hpp"
#include "scenario/size_distribution.hpp"
#include "scenario3d/build3.hpp"

namespace talus {
namespace {

std::string pour3d_text() {
  for (const auto& b : cli::builtin_scenarios())
    if (b.name == "pour3d") return std::string(b.text);
  ADD_FAILURE() << "no built-in pour3d";
  return {};
}

Scenario3 pour3d(const std::vector<std::string>& set = {}) {
  return load_scenario3(pour3d_text(), "pour3d", set);
}

// The error a 3D scenario with `set` gives, or "" if it loads.
std::string refusal(const std::vector<std::string>& set) {
  try {
    pour3d(set);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

TEST(Scenario3, ThePour3dBuiltinReloadsFromItsResolvedForm) {
  const Scenario3 s = pour3d();
  EXPECT_EQ(s.particles.count, 1000u);
  EXPECT_EQ(s.simulation.gravity.z, -9.81);
  EXPECT_EQ(s.simulation.normal_law, law_id<HertzViscoelastic>);
  const std::string resolved = to_toml(s);
  EXPECT_EQ(to_toml(load_scenario3(resolved, "resolved")), resolved);
  EXPECT_EQ(scenario_dimension(toml::parse(resolved), "resolved"), 3);
}

TEST(Scenario3, StressRegionsReadAndReloadOrAreRefusedSayingWhy) {
  const std::string low = "{name='low', region=[0, 0, 0, 0.03, 0.03, 0.01]}";
  const Scenario3 s = pour3d({"output.stress=true", "output.stress_region=[0,0,0,0.03,0.03,0.06]",
                              "output.stress_regions=[" + low + "]"});
  ASSERT_TRUE(s.output.stress_region);
  EXPECT_EQ(s.output.stress_region->hi.z, 0.06);
  ASSERT_EQ(s.output.stress_regions.size(), 1u);
  EXPECT_EQ(s.output.stress_regions[0].name, "low");
  EXPECT_EQ(s.output.stress_regions[0].region.hi.z, 0.01);
  const std::string resolved = to_toml(s);
  EXPECT_EQ(to_toml(load_scenario3(resolved, "resolved")), resolved);
  const auto says = [](const std::vector<std::string>& set, const std::string& words) {
    const std::string e = refusal(set);
    EXPECT_NE(e.find(words), std::string::npos) << set.back() << ": " << e;
  };
  says({"output.stress_regions=[" + low + "]"}, "needs output.stress = true");
  says({"output.stress_region=[0,0,0,1,1,1]"}, "needs output.stress = true");
  says({"output.stress=true", "output.stress_region=[0,0,0,1,1]"},
       "[x_min, y_min, z_min, x_max, y_max, z_max]");
  says({"output.stress=true", "output.stress_regions=[" + low + ", " + low + "]"},
       "'low' is given twice");
  says({"output.stress=true", "output.stress_regions=[{name='Low', region=[0,0,0,1,1,1]}]"},
       "lower-case letters, digits and _");
  says({"output.stress=true", "output.stress_regions=[{name='low'}]"},
       "'output.stress_regions.0.region'");
}

TEST(Scenario3, GearIsTheIntegratorAsked) {
  const Scenario3 s = pour3d({"simulation.integrator=gear"});
  EXPECT_EQ(s.simulation.integrator, Integrator::gear);
  EXPECT_EQ(build_scenario3(s).settings.integrator, Integrator::gear);
  EXPECT_NE(to_toml(s).find("integrator = 'gear'"), std::string::npos) << to_toml(s);
  EXPECT_EQ(pour3d().simulation.integrator, Integrator::verlet);
}

TEST(Scenario3, WhatThe3DEngineHasNotIsRefusedByName) {
  const auto says = [](const std::vector<std::string>& set, const std::string& words) {
    const std::string e = refusal(set);
    EXPECT_NE(e.find(words), std::string::npos) << set[0] << ": " << e;
  };
  says({"particles.shape=disk"}, "a 3D scenario's grains are spheres");
  says({"packing.method=lattice"}, "[packing] is not there yet in 3D");
  says({"frost.model=front"}, "[frost] is not there yet in 3D");
  says({"geometry.builder=silo"}, "'geometry.builder'");
  says({"geometry.box=[0,0,0,1,1]"}, "[x_min, y_min, z_min, x_max, y_max, z_max]");
  says({"geometry.periodic=xyz", "geometry.open_top=false"}, "no top or floor");
  says({"simulation.gravity=[0,-9.81]"}, "expected [x, y, z]");
  says({"particles.material=sand"}, "no material named 'sand'");
  says({"simulation.dimension=4"}, "an integer in [3, 3]");
}

TEST(Scenario3, TheDimensionIsTwoOrThreeAndThe2DLoaderSendsThreeToTalusRun) {
  EXPECT_EQ(scenario_dimension(toml::parse("name = 'a'"), "a.toml"), 2);
  EXPECT_THROW(scenario_dimension(toml::parse("[simulation]\ndimension = 1"), "a.toml"),
               ScenarioError);
  try {
    load_scenario(pour3d_text(), "pour3d");
    FAIL() << "the 2D loader took a 3D scenario";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("is run by `talus run` alone"), std::string::npos)
        << e.what();
  }
}

TEST(Scenario3, TheSpheresStartInTheBoxAsTheSeedSays) {
  const Scenario3 s = pour3d({"particles.count=300"});
  const BuiltScenario3 a = build_scenario3(s), b = build_scenario3(s);
  const BuiltScenario3 other =
      build_scenario3(pour3d({"particles.count=300", "simulation.seed=2"}));
  const Spheres& p = a.scene.spheres;
  ASSERT_EQ(p.size(), 300u);
  const auto [r_min, r_max] = radius_range(s.particles.size);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_GE(p.radius[i], r_min);
    EXPECT_LE(p.radius[i], r_max);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(component(p.position[i], k) - p.radius[i], component(s.geometry.lo, k));
      EXPECT_LE(component(p.position[i], k) + p.radius[i], component(s.geometry.hi, k));
    }
    EXPECT_EQ(p.position[i].x, b.scene.spheres.position[i].x);
  }
  EXPECT_NE(p.position[7].x, other.scene.spheres.position[7].x);
  EXPECT_EQ(a.scene.plates.size(), 5u); // open top
  EXPECT_EQ(build_scenario3(pour3d({"geometry.periodic=xy"})).scene.plates.size(), 1u);
  EXPECT_NEAR(a.settings.timestep, a.collision_time / s.simulation.timestep_factor, 1e-18);
}

TEST(Scenario3, ACountTheBoxCannotHoldOrATimestepTooLongIsRefused) {
  try {
    build_scenario3(pour3d({"particles.count=100000"}));
    FAIL() << "100000 spheres fitted";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("'particles.count': 100000 spheres do not fit"),
              std::string::npos)
        << e.what();
  }
  try {
    build_scenario3(pour3d({"simulation.timestep=1e-4"}));
    FAIL() << "a timestep of most of a collision was taken";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("'simulation.timestep'"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace talus
