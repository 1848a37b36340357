// A rough floor of glued spheres in a 3D scenario (geometry.rough_floor, scenario3d/build3.cpp):
// - it tiles the floor with fixed spheres of the particles' middle radius, a whole number of them
//   along each side, resting on the floor, and the free spheres start above them;
// - a frictionless bed come to rest on it in a box periodic across: the fixed spheres and the
//   floor plate under them carry the bed's weight, the fixed spheres staying where they were;
// - what it cannot be is refused by name.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/builtin_scenarios.hpp"
#include "io/lammps_export3.hpp"
#include "scenario/file/load3.hpp"
#include "scenario/size_distribution.hpp"
#include "scenario3d/build3.hpp"

namespace talus {
namespace {

Scenario3 rough_bed(const std::vector<std::string>& more = {}) {
  std::string text;
  for (const auto& b : cli::builtin_scenarios())
    if (b.name == "pour3d") text = b.text;
  std::vector<std::string> set{"particles.count=60",
                               "geometry.box=[0, 0, 0, 0.03, 0.03, 0.03]",
                               "geometry.periodic=xy",
                               "geometry.rough_floor=true",
                               "simulation.tangential_law=none",
                               "simulation.timestep_factor=20"};
  set.insert(set.end(), more.begin(), more.end());
  return load_scenario3(text, "rough bed", set);
}

TEST(RoughFloor3, GluedSpheresTileTheFloorUnderTheFreeOnes) {
  const Scenario3 s = rough_bed();
  const BuiltScenario3 b = build_scenario3(s);
  const Spheres& p = b.scene.spheres;
  const auto [r_min, r_max] = radius_range(s.particles.size);
  const double r = 0.5 * (r_min + r_max);
  const auto along = static_cast<std::size_t>(0.03 / (2.0 * r)); // spheres along each side
  std::size_t fixed = 0;
  double highest_base = 0.0, lowest_free = 1.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.is_free(i)) {
      lowest_free = std::min(lowest_free, p.position[i].z - p.radius[i]);
      continue;
    }
    ++fixed;
    EXPECT_EQ(p.radius[i], r);
    EXPECT_GE(p.position[i].z, r);       // on the floor, not in it
    EXPECT_LE(p.position[i].z, 1.2 * r); // raised by up to a fifth of the radius
    highest_base = std::max(highest_base, p.position[i].z + r);
  }
  EXPECT_EQ(fixed, along * along);
  EXPECT_EQ(p.size(), fixed + 60);
  EXPECT_GT(lowest_free, highest_base);
  EXPECT_EQ(to_toml(load_scenario3(to_toml(s), "resolved")), to_toml(s));
}

TEST(RoughFloor3, ABedAtRestOnItWeighsOnTheGluedSpheresAndTheFloor) {
  const BuiltScenario3 b = build_scenario3(rough_bed());
  Simulation3 sim(b.scene, b.settings);
  sim.run(static_cast<std::uint64_t>(0.4 / b.settings.timestep));
  const Spheres& p = sim.scene().spheres;
  double weight = 0.0, kinetic = 0.0;
  Vec3 carried = sim.scene().plates[0].force;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!p.is_free(i)) {
      carried += p.force[i];
      // spheres are renumbered as the run goes: the one with the same id
      const Spheres& start = b.scene.spheres;
      for (std::size_t k = 0; k < start.size(); ++k) {
        if (start.id[k] == p.id[i]) {
          EXPECT_EQ(p.position[i].z, start.position[k].z) << "a glued sphere moved";
        }
      }
      continue;
    }
    weight += p.mass[i] * 9.81;
    kinetic += 0.5 * p.mass[i] * norm2(p.velocity[i]);
  }
  // near rest: the motion left a hundred-thousandth of the bed's weight falling by a millimetre
  ASSERT_LT(kinetic, 1e-5 * weight * 1e-3) << "the bed has not come to rest";
  // the weight rests on the base, to the accelerations of the bed's last trembling: 1e-3
  EXPECT_NEAR(-carried.z, weight, 1e-3 * weight) << kinetic;
}

TEST(RoughFloor3, ARoughFloorWithoutAFloorOrInLammpsIsRefused) {
  EXPECT_THROW(rough_bed({"geometry.periodic=xyz"}), ScenarioError);
  EXPECT_THROW(check_lammps_export(rough_bed()), InvalidArgument);
}

} // namespace
} // namespace talus
