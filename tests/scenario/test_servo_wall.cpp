// A lid held at a load by the servo controller (drivers/servo.hpp), on a bed of frictionless
// grains in a box: the lid carries the load asked, and the floor the load and the bed's weight.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <variant>

#include "io/checkpoint.hpp"
#include "io/lammps_export.hpp"
#include "scenario/file/load.hpp"
#include "scenario/file/toml_reader.hpp"
#include "support/run_dir.hpp"
#include "support/run_scenario.hpp"
#include "support/thermo_rows.hpp"

namespace talus {
namespace {

using testing::mean_of;

// 100 frictionless spheres settled in a box 0.1 m wide (they weigh about 0.7 N); the lid starts
// 0.16 m up and comes down at up to 1 m/s.
const char* bed = R"(
name = "servo_bed"
[simulation]
duration = 0.5
tangential_law = "none"
[[materials]]
name = "grain"
friction = 0.0
[particles]
count = 100
size = { mean_radius = 0.004, spread = 0.001 }
[packing]
method = "sedimentation"
[geometry]
builder = "box"
width = 0.1
height = 0.16
[output]
thermo_interval = 0.005
snapshot_interval = 0
picture = false
)";

const char* servo_lid = R"(
[[drivers]]
type = "servo"
target = "lid"
direction = [0, -1]
force = 2.0
)";

double weight_of_grains(const BuiltScenario& b) {
  double w = 0.0;
  for (std::size_t i = 0; i < b.world.particles.size(); ++i)
    if (b.world.particles.is_free(i)) w += b.world.particles.mass[i] * 9.81;
  return w;
}

// The lid reaches the bed after about 0.05 s and holds 2 N; a stage then asks for 4 N. Over the
// last 0.15 s of each stage: the lid's load within 0.5% of the target (the bed's rattling grains
// move it by a few parts in a thousand; every row within 5%), and the floor carries the load and
// the weight within 1% (frictionless walls take no vertical force; what is left is the grains'
// motion).
TEST(ServoWall, HoldsTheLoadItIsAskedAndTheFloorCarriesItWithTheWeight) {
  const Scenario s = load_scenario(std::string(bed) + servo_lid + R"(
[[stages]]
name = "press 2"
duration = 0.3
[[stages]]
name = "press 4"
duration = 0.3
set = { "drivers.0.force" = 4.0 }
)",
                                   "servo_bed.toml", {"simulation.duration=0.6"});
  const BuiltScenario b = build_scenario(s);
  const double weight = weight_of_grains(b);
  const std::filesystem::path dir = testing::fresh_dir("servo_bed");
  ASSERT_EQ(testing::run_quietly(s, dir), cli::exit_completed);
  const auto rows = testing::thermo_rows(dir);
  for (const auto& [target, from] : {std::pair{2.0, 0.15}, {4.0, 0.45}}) {
    const double lid = mean_of(rows, "force_lid_y", from, from + 0.15);
    const double floor = -mean_of(rows, "force_floor_y", from, from + 0.15);
    EXPECT_NEAR(lid, target, 0.005 * target);
    EXPECT_NEAR(floor, target + weight, 0.01 * (target + weight));
    for (const auto& row : rows) {
      if (row.at("time") < from || row.at("time") >= from + 0.15) continue;
      EXPECT_NEAR(row.at("force_lid_y"), target, 0.05 * target) << row.at("time");
    }
  }
  std::filesystem::remove_all(dir);
}

// A run stopped and resumed goes on as the whole run did: the servo's state is in the
// checkpoint.
TEST(ServoWall, AResumedRunIsTheWholeRun) {
  const Scenario s = load_scenario(std::string(bed) + servo_lid, "servo_bed.toml",
                                   {"simulation.duration=0.2", "output.checkpoint_interval=0.05"});
  const std::filesystem::path whole = testing::fresh_dir("servo_whole");
  const std::filesystem::path parts = testing::fresh_dir("servo_parts");
  ASSERT_EQ(testing::run_quietly(s, whole), cli::exit_completed);
  ASSERT_NE(testing::run_quietly(s, parts, 0.12), cli::exit_completed);
  ASSERT_EQ(testing::resume_quietly(parts), cli::exit_completed);
  EXPECT_EQ(read_file((whole / "thermo.csv").string()), read_file((parts / "thermo.csv").string()));
  std::filesystem::remove_all(whole);
  std::filesystem::remove_all(parts);
}

// A stress target is a force per width of the lid: 20 N/m on a lid 0.1 m wide is 2 N.
TEST(ServoWall, AStressIsAForcePerWidth) {
  const Scenario s = load_scenario(std::string(bed) + R"(
[[drivers]]
type = "servo"
target = "lid"
direction = [0, -1]
stress = 20.0
)",
                                   "servo_stress.toml", {"packing.method=\"lattice\""});
  const BuiltScenario b = build_scenario(s);
  const Servo& servo = std::get<Servo>(b.world.drivers.back().motion);
  EXPECT_NEAR(servo.force, 2.0, 1e-12);
  EXPECT_EQ(servo.max_speed, s.simulation.impact_speed);
}

TEST(ServoWall, BadServosAreRefusedWithTheKey) {
  const auto refused = [](const std::string& driver, const std::string& words) {
    try {
      build_scenario(
          load_scenario(std::string(bed) + driver, "bad.toml", {"packing.method=\"lattice\""}));
      ADD_FAILURE() << "accepted: " << driver;
    } catch (const ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  const std::string head = "[[drivers]]\ntype = \"servo\"\ntarget = \"lid\"\n";
  refused(head + "force = 2.0\n", "direction");
  refused(head + "direction = [0, -1]\n", "one target");
  refused(head + "direction = [0, -1]\nforce = 1.0\nstress = 2.0\n", "one target");
  refused(head + "direction = [0, -1]\nforce = 1.0\nrelaxation = 1.5\n", "relaxation");
  refused(head + "direction = [0, 0]\nforce = 1.0\n", "non-zero");
  refused(head + "direction = [1, 0]\nstress = 1.0\n", "width");
  refused("[[drivers]]\ntype = \"translate\"\ntarget = \"lid\"\nforce = 1.0\n", "only a servo");
  // a wall moved by two drivers would follow the last alone: the lid, and all walls shaken
  refused(head + "direction = [0, -1]\nforce = 1.0\n[[drivers]]\ntype = \"vibrate\"\n" +
              "target = \"walls\"\n",
          "a wall follows one driver");
  // exported to LAMMPS: refused with the reason
  const Scenario s = load_scenario(std::string(bed) + servo_lid, "servo_bed.toml");
  EXPECT_THROW(check_lammps_export(s), InvalidArgument);
}

} // namespace
} // namespace talus
