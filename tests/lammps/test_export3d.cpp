// talus export lammps of a 3D scenario (native/io/lammps_export3.cpp): the deck, data and masses
// of pour3d run in LAMMPS as the native engine runs the scenario, to rounding, through the
// spheres' fall onto the floor and each other (with the scenario's Verlet set to LAMMPS'
// half-step velocity); and what LAMMPS cannot express is refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/lammps_export3.hpp"
#include "native3d.hpp"
#include "scenario/file/load3.hpp"

namespace talus::lammps_test {
namespace {

Scenario3 pour3d(const std::vector<std::string>& set) {
  const std::string file = std::string(TALUS_SOURCE_DIR) + "/inputs/pour3d/scenario.toml";
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return load_scenario3(text.str(), file, set);
}

// The case runs where it was written: read_data and include name its files relative to it.
class InFolder {
public:
  explicit InFolder(const std::filesystem::path& d) : before_(std::filesystem::current_path()) {
    std::filesystem::current_path(d);
  }
  ~InFolder() { std::filesystem::current_path(before_); }
  InFolder(const InFolder&) = delete;
  InFolder& operator=(const InFolder&) = delete;

private:
  std::filesystem::path before_;
};

// 150 spheres fall from the lattice onto the floor and onto each other: 6000 steps take the
// lowest layer through its first bounces. Both engines start from the written case's numbers
// (the shortest text of every double) and share the kernel and the plates' lines; the
// integrators round differently, a few ulp a step that the collisions amplify: 1e-15 m of the
// positions, 1e-12 m/s of the speeds (about 0.3 m/s), 1e-9 rad/s of the spins.
TEST(Export3D, Pour3dRunsInLammpsAsInTheNativeEngine) {
  const Scenario3 s = pour3d({"particles.count=150", "simulation.verlet_velocity=half_step"});
  const BuiltScenario3 built = build_scenario3(s);
  const LammpsCase c = export_lammps(s, built, "talus export lammps pour3d (test)");
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("talus-export3d-" + std::to_string(::getpid()));
  write_lammps_case(c, dir.string());
  const int steps = 6000;
  LammpsInstance l;
  {
    const InFolder here(dir);
    l.commands({"variable steps index " + std::to_string(steps),
                "variable snapshot_every index 1000000", "include in.pour3d"});
  }
  std::filesystem::remove_all(dir);
  Simulation3 native(built.scene, built.settings);
  std::size_t on_plates = 0;
  for (int k = 0; k < steps; ++k) {
    native.step();
    on_plates += native.last_pass().on_plates;
  }
  ASSERT_GT(on_plates, 1000u) << "the spheres did not reach the floor";
  const Difference d = between(l, native);
  std::printf("pour3d exported: %.2e m, %.2e m/s, %.2e rad/s\n", d.position, d.velocity, d.spin);
  EXPECT_LT(d.position, 1e-15);
  EXPECT_LT(d.velocity, 1e-12);
  EXPECT_LT(d.spin, 1e-9);
}

TEST(Export3D, WhatLammpsCannotExpressIsRefused) {
  const auto refusal = [](const std::string& set) -> std::string {
    try {
      check_lammps_export(pour3d({set}));
    } catch (const InvalidArgument& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(refusal("simulation.lever_arm=radius").find("key 'simulation.lever_arm'"),
            std::string::npos);
  EXPECT_NE(refusal("simulation.linear_damping=classic").find("key 'simulation.linear_damping'"),
            std::string::npos);
  EXPECT_EQ(refusal("simulation.seed=3"), "");
}

} // namespace
} // namespace talus::lammps_test
