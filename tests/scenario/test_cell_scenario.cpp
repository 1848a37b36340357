// The deforming periodic cell as a scenario gives it ([[drivers]] type = "cell"): a cell held at
// a pressure that a stage changes, thermo.csv's pressure and cell columns, a run stopped and
// resumed, the keys refused with their reason, and the LAMMPS export.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

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

// 256 frictionless bidisperse disks on a lattice in a periodic box 0.25 m wide, no gravity.
const char* gas = R"(
name = "cell_gas"
[simulation]
duration = 0.6
tangential_law = "none"
normal_law = "linear"
gravity = [0.0, 0.0]
impact_speed = 0.1
[[materials]]
name = "disk"
density = 2650.0
normal_stiffness = 1.0e5
restitution = 0.2
friction = 0.0
[particles]
count = 256
shape = "disk"
material = "disk"
size = { distribution = "discrete", radii = [0.005, 0.007], fractions = [0.5, 0.5] }
[packing]
method = "lattice"
region = [0.0, 0.0, 0.25, 0.25]
[geometry]
periodic = "xy"
box = [0.0, 0.0, 0.25, 0.25]
[output]
thermo_interval = 0.01
snapshot_interval = 0
picture = false
stress = true
)";

const char* held = R"(
[[drivers]]
type = "cell"
pressure = 200.0
max_strain_rate = 1.0
)";

// The cell shrinks onto the grains and holds 200 N/m, then a stage lets it down to 50 N/m: over
// the last 0.1 s of each stage thermo.csv's pressure (the stress over the cell as it is,
// analysis/stress.hpp) is the target within 1% (the packing creeps and rattles a little), the
// cell's sides are equal, and the packing is jammed: its packing fraction past 0.8 (a quick
// compression jams these disks below the 0.84 of a slow one; the packing then creeps).
TEST(CellScenario, HoldsThePressureAStageAsksFor) {
  const Scenario s = load_scenario(std::string(gas) + held + R"(
[[stages]]
name = "p 200"
duration = 0.4
[[stages]]
name = "p 50"
duration = 0.3
set = { "drivers.0.pressure" = 50.0 }
)",
                                   "cell_gas.toml", {"simulation.duration=0.7"});
  const std::filesystem::path dir = testing::fresh_dir("cell_gas");
  ASSERT_EQ(testing::run_quietly(s, dir), cli::exit_completed);
  const auto rows = testing::thermo_rows(dir);
  for (const auto& [target, from] : {std::pair{200.0, 0.3}, {50.0, 0.6}}) {
    EXPECT_NEAR(mean_of(rows, "pressure", from, from + 0.1), target, 0.01 * target);
    EXPECT_GT(mean_of(rows, "packing_fraction", from, from + 0.1), 0.8);
  }
  EXPECT_EQ(rows.back().at("cell_x"), rows.back().at("cell_y"));
  EXPECT_LT(rows.back().at("cell_x"), 0.25);
  std::filesystem::remove_all(dir);
}

// A run stopped and resumed goes on as the whole run did: the cell's state and the box at the
// neighbour list's build are in the checkpoint.
TEST(CellScenario, AResumedRunIsTheWholeRun) {
  const Scenario s = load_scenario(std::string(gas) + held, "cell_gas.toml",
                                   {"simulation.duration=0.3", "output.checkpoint_interval=0.05"});
  const std::filesystem::path whole = testing::fresh_dir("cell_whole");
  const std::filesystem::path parts = testing::fresh_dir("cell_parts");
  ASSERT_EQ(testing::run_quietly(s, whole), cli::exit_completed);
  ASSERT_NE(testing::run_quietly(s, parts, 0.17), cli::exit_completed);
  ASSERT_EQ(testing::resume_quietly(parts), cli::exit_completed);
  EXPECT_EQ(read_file((whole / "thermo.csv").string()), read_file((parts / "thermo.csv").string()));
  std::filesystem::remove_all(whole);
  std::filesystem::remove_all(parts);
}

TEST(CellScenario, BadCellsAreRefusedWithTheKey) {
  const auto refused = [](const std::string& text, const std::string& words) {
    try {
      build_scenario(load_scenario(text, "bad.toml"));
      ADD_FAILURE() << "accepted: " << text;
    } catch (const ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  const std::string head = std::string(gas) + "[[drivers]]\ntype = \"cell\"\n";
  refused(head + "target = \"walls\"\nstrain_rate = [-1, -1]\n", "no target");
  refused(head, "strain_rate = [x, y] (1/s), pressure (N/m) or shear_rate");
  refused(head + "shear_rate = 1.0\nstrain_rate = [1, 0]\n", "keeps its width");
  refused(head + "strain_rate = [-1, -1]\npressure = 10.0\n", "not both");
  refused(head + "pressure = 10.0\n", "max_strain_rate");
  refused(head + "strain_rate = [-1, -1]\nmax_strain_rate = 1.0\n", "only a cell held");
  refused(head + "pressure = 10.0\nmax_strain_rate = 1.0\nrelaxation = 2.0\n", "relaxation");
  refused(std::string(gas) + "[[drivers]]\ntype = \"translate\"\nstrain_rate = [1, 1]\n",
          "only a cell driver");
  refused(head + "strain_rate = [-1, -1]\n[[drivers]]\ntype = \"cell\"\nstrain_rate = [1, 1]\n",
          "two cell drivers");
  // a direction that does not wrap, and walls, which the cell would leave behind
  std::string open = std::string(gas) + "[[drivers]]\ntype = \"cell\"\nstrain_rate = [0, -1]\n";
  open.replace(open.find("periodic = \"xy\""), 15, "periodic = \"x\" ");
  refused(open, "not periodic");
  refused(head + "strain_rate = [-1, -1]\n[[geometry.segments]]\na = [0, 0]\nb = [0.25, 0]\n",
          "wall segments");
}

// A cell at a strain rate is LAMMPS' fix deform with its true strain rate, every atom remapped;
// one held at a pressure has no counterpart with the same controller, and is refused.
TEST(CellScenario, TheExportWritesFixDeformForARate) {
  const Scenario rate = load_scenario(
      std::string(gas) + "[[drivers]]\ntype = \"cell\"\nstrain_rate = [-0.5, 0.25]\n", "r.toml");
  const LammpsCase out = export_lammps(rate, build_scenario(rate), "test");
  EXPECT_NE(out.deck.find("fix cell all deform 1 x trate -0.5 y trate 0.25 remap x\n"),
            std::string::npos)
      << out.deck;
  const Scenario pressure = load_scenario(std::string(gas) + held, "p.toml");
  EXPECT_THROW(check_lammps_export(pressure), InvalidArgument);
}

} // namespace
} // namespace talus
