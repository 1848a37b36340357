// Listed fixed grains are the wall group "fixed": the force the grains put on them is recorded,
// and a driver moves them by that name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "io/checkpoint.hpp"
#include "scenario/file/load.hpp"
#include "scenario/file/toml_reader.hpp"
#include "support/run_dir.hpp"
#include "support/run_scenario.hpp"
#include "support/thermo_rows.hpp"

namespace talus {
namespace {

// A free grain resting on a fixed one, on the line of their centres.
const char* perched = R"(
name = "perched"
[simulation]
duration = 0.3
[particles]
list = [ { position = [0.05, 0.02], radius = 0.01, kind = "fixed" },
         { position = [0.05, 0.04], radius = 0.01 } ]
[geometry]
builder = "box"
width = 0.1
height = 0.1
[output]
thermo_interval = 0.01
snapshot_interval = 0
picture = false
)";

// At rest, the perched grain presses on the fixed one with its weight, m g downward, to the
// part in a thousand its damped bounce leaves after 0.3 s.
TEST(FixedGrains, TheForceOnThemIsRecorded) {
  const Scenario s = load_scenario(perched, "perched.toml");
  const BuiltScenario b = build_scenario(s);
  ASSERT_EQ(b.groups.at("fixed").particles, std::vector<std::uint32_t>{0u});
  const double weight = b.world.particles.mass[1] * 9.81;
  const std::filesystem::path dir = testing::fresh_dir("fixed_force");
  ASSERT_EQ(testing::run_quietly(s, dir), cli::exit_completed);
  std::map<std::string, double> row = testing::last_thermo_row(dir);
  ASSERT_TRUE(row.count("force_fixed_y"));
  EXPECT_NEAR(row["force_fixed_y"], -weight, 1e-3 * weight);
  EXPECT_NEAR(row["force_fixed_x"], 0.0, 1e-9 * weight);
  std::filesystem::remove_all(dir);
}

// A driver with target = "fixed" moves the fixed grains: they become moved grains, carried at
// its velocity, and carry the perched grain along.
TEST(FixedGrains, ADriverMovesThemByName) {
  const Scenario s = load_scenario(std::string(perched) + R"(
[[drivers]]
type = "translate"
target = "fixed"
velocity = [0.0, 0.05]
)",
                                   "lifted.toml", {"simulation.duration=0.2"});
  const BuiltScenario b = build_scenario(s);
  EXPECT_EQ(b.world.particles.kind[0], Kind::moved);
  const std::filesystem::path dir = testing::fresh_dir("fixed_driven");
  ASSERT_EQ(testing::run_quietly(s, dir), cli::exit_completed);
  const Checkpoint c = decode_checkpoint(read_file((dir / "checkpoint.bin").string()), "x");
  const Particles& p = c.state.world.particles;
  EXPECT_NEAR(p.position[0].y, 0.02 + 0.05 * c.state.time, 1e-12);
  EXPECT_GT(p.position[1].y, 0.04 + 0.009); // lifted on top of it
  std::filesystem::remove_all(dir);
}

// A stage change starts the engine again from its state, with its count of renumberings back
// at 0. The run's indices of the fixed grains must not be mapped then by the old run's last
// renumbering (there was none to map by: an empty map read out of bounds and the run crashed),
// and the group keeps its grains and its force column through a change of walls: at the end,
// the column is the force on the fixed grain, found by its kind in the last checkpoint (30
// grains renumbered every 7 steps around it).
TEST(FixedGrains, AStageChangeKeepsThemAndTheirForce) {
  const Scenario s =
      load_scenario(std::string(perched) + R"(
[[geometry.segments]]
a = [0.0, 0.09]
b = [0.01, 0.09]
[[stages]]
name = "a"
duration = 0.1
[[stages]]
name = "b"
duration = 0.2
set = { "geometry.segments" = [] }
)",
                    "staged.toml", {"simulation.sort_every=7", "particles.count=30"});
  const std::filesystem::path dir = testing::fresh_dir("fixed_staged");
  ASSERT_EQ(testing::run_quietly(s, dir), cli::exit_completed);
  std::map<std::string, double> row = testing::last_thermo_row(dir);
  ASSERT_TRUE(row.count("force_fixed_y"));
  const Checkpoint c = decode_checkpoint(read_file((dir / "checkpoint.bin").string()), "x");
  const Particles& p = c.state.world.particles;
  const auto fixed = static_cast<std::size_t>(std::find(p.kind.begin(), p.kind.end(), Kind::fixed) -
                                              p.kind.begin());
  ASSERT_LT(fixed, p.size());
  EXPECT_GT(c.state.steps, 7u * 10u); // renumbered many times
  EXPECT_NE(p.force[fixed].y, 0.0);
  EXPECT_NEAR(row["force_fixed_y"], p.force[fixed].y, 1e-8 * std::abs(p.force[fixed].y));
  EXPECT_NEAR(row["force_fixed_x"], p.force[fixed].x, 1e-8 * std::abs(p.force[fixed].y));
  std::filesystem::remove_all(dir);
}

// Hand-made walls join the groups they name: a plate under the perched grains (group "plate"),
// driven up by name, lifts them, and thermo.csv has its force; the group's name is checked.
TEST(FixedGrains, NamedSegmentGroupsAreDrivenAndMeasured) {
  const Scenario s = load_scenario(std::string(perched) + R"(
[[geometry.segments]]
a = [0.02, 0.005]
b = [0.08, 0.005]
group = "plate"
[[drivers]]
type = "translate"
target = "plate"
velocity = [0.0, 0.02]
)",
                                   "plate.toml", {"simulation.duration=0.2"});
  const BuiltScenario b = build_scenario(s);
  ASSERT_EQ(b.groups.at("plate").segments.size(), 1u);
  EXPECT_FALSE(b.groups.count("extra"));
  const std::filesystem::path dir = testing::fresh_dir("segment_group");
  ASSERT_EQ(testing::run_quietly(s, dir), cli::exit_completed);
  const Checkpoint c = decode_checkpoint(read_file((dir / "checkpoint.bin").string()), "x");
  const Segment& plate = c.state.world.walls[b.groups.at("plate").segments[0]];
  EXPECT_NEAR(plate.a.y, 0.005 + 0.02 * c.state.time, 1e-12);
  std::map<std::string, double> row = testing::last_thermo_row(dir);
  EXPECT_TRUE(row.count("force_plate_y"));
  std::filesystem::remove_all(dir);
  for (const char* bad : {"walls", "fixed", "top plate", ""})
    EXPECT_THROW(load_scenario(std::string(perched) +
                                   "[[geometry.segments]]\na = [0, 0]\nb = [1, "
                                   "0]\ngroup = \"" +
                                   bad + "\"\n",
                               "bad.toml"),
                 ScenarioError)
        << bad;
}

} // namespace
} // namespace talus
