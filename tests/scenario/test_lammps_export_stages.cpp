// talus export lammps of a deforming cell in stages (io/lammps_stages.cpp): a Lees-Edwards cell
// as LAMMPS' tilted box, the stages as one LAMMPS run each with the cell's fix between them, and
// what is refused. (The validation case shear_cell runs such a deck: docs/validation.md.)
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "io/lammps_export.hpp"
#include "scenario/file/load.hpp"
#include "simulation/simulation.hpp"

namespace talus {
namespace {

// 64 frictional disks on a lattice in a box periodic in x and y, no gravity: a cell that
// shrinks along y, then shears at a constant volume.
const char* stages_head = R"(
name = "cell_stages"
[simulation]
duration = 1.0
timestep = 1.0e-4
normal_law = "linear"
tangential_law = "cundall_strack"
gravity = [0.0, 0.0]
[[materials]]
name = "disk"
density = 2650.0
normal_stiffness = 1.0e5
restitution = 0.2
friction = 0.4
[particles]
count = 64
shape = "disk"
material = "disk"
size = { distribution = "uniform", mean_radius = 0.005, spread = 0.001 }
[packing]
method = "lattice"
region = [0.0, 0.0, 0.1, 0.12]
[geometry]
periodic = "xy"
box = [0.0, 0.0, 0.1, 0.12]
[[drivers]]
type = "cell"
)";

const std::string compress_then_shear = std::string(stages_head) + R"(strain_rate = [0.0, -0.5]
[[stages]]
name = "compress"
duration = 0.25
[[stages]]
name = "shear"
set = { "drivers.0.strain_rate" = [0.0, 0.0], "drivers.0.shear_rate" = 2.0 }
)";

LammpsCase exported(const std::string& text) {
  const Scenario s = load_scenario(text, "cell_stages.toml");
  return export_lammps(s, build_scenario(s), "test");
}

std::string refusal(const std::string& text) {
  try {
    check_lammps_export(load_scenario(text, "cell_stages.toml"));
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "(not refused)";
}

// The deck runs the stages for the native stages' steps (each duration rounded up, the last to
// the run's end), the cell's fix replaced between; the box is triclinic from the start.
TEST(LammpsExportStages, ACellInStagesIsOneRunPerStage) {
  const LammpsCase c = exported(compress_then_shear);
  EXPECT_NE(c.data.find("zlo zhi\n0 0 0 xy xz yz\n"), std::string::npos) << c.data;
  const std::uint64_t first = steps_until(0.25, 1.0e-4);
  const std::uint64_t all = static_cast<std::uint64_t>(std::llround(1.0 / 1.0e-4));
  const std::string runs = fmt::format("fix cell all deform 1 x trate 0 y trate -0.5 remap x\n"
                                       "# stage 0 (compress): {0} steps\nrun {0}\n"
                                       "unfix cell\nfix cell all deform 1 xy erate 2 remap v\n"
                                       "# stage 1 (shear): {1} steps\nrun {1}\n",
                                       first, all - first);
  EXPECT_NE(c.deck.find(runs), std::string::npos) << c.deck;
  EXPECT_EQ(c.deck.find("run ${steps}"), std::string::npos);
  // the stress the cross-check compares, from the start (thermo_style once for every run)
  EXPECT_NE(c.deck.find("compute contact_stress all pressure NULL virial\n"), std::string::npos);
  EXPECT_NE(c.deck.find(" c_contact_stress[1] c_contact_stress[2] c_contact_stress[4] vol\n"),
            std::string::npos);
}

// A cell sheared from the start: the tilt grows at the shear rate with the images' velocity.
TEST(LammpsExportStages, AShearedCellIsATiltedBox) {
  const LammpsCase c = exported(std::string(stages_head) + "shear_rate = 1.5\n");
  EXPECT_NE(c.deck.find("fix cell all deform 1 xy erate 1.5 remap v\nrun ${steps}\n"),
            std::string::npos)
      << c.deck;
  EXPECT_NE(c.data.find("0 0 0 xy xz yz\n"), std::string::npos);
  // without a shear in any stage the box stays orthogonal, as LAMMPS' own examples write it
  const LammpsCase plain = exported(std::string(stages_head) + "strain_rate = [0.0, -0.5]\n");
  EXPECT_EQ(plain.data.find("xy xz yz"), std::string::npos);
}

TEST(LammpsExportStages, RefusesWhatOneFixDeformPerStageCannotSay) {
  // a cell that strains and shears at once, from the start or in a stage
  EXPECT_NE(refusal(std::string(stages_head) + "strain_rate = [0.0, -0.5]\nshear_rate = 1.0\n")
                .find("key 'drivers': a cell that strains and shears at once"),
            std::string::npos);
  std::string both = compress_then_shear;
  const std::string stop = "\"drivers.0.strain_rate\" = [0.0, 0.0], ";
  both.replace(both.find(stop), stop.size(), "");
  EXPECT_NE(refusal(both).find("key 'stages.1.set': a cell that strains and shears at once"),
            std::string::npos)
      << refusal(both);
  // a stage that changes anything but the cell's rates, or that ends on a condition
  std::string gravity = compress_then_shear;
  const std::string shear = "\"drivers.0.shear_rate\" = 2.0";
  gravity.replace(gravity.find(shear), shear.size(), "\"simulation.gravity\" = [0.0, -9.81]");
  EXPECT_NE(refusal(gravity).find("key 'stages.1.set': a stage's change of 'simulation.gravity'"),
            std::string::npos)
      << refusal(gravity);
  std::string until = compress_then_shear;
  until.insert(until.find("duration = 0.25"), "until = \"kinetic_below\"\nkinetic = 1.0\n");
  EXPECT_NE(refusal(until).find("key 'stages.0.until'"), std::string::npos) << refusal(until);
  // a cell held at a pressure has no counterpart with the same controller
  EXPECT_NE(refusal(std::string(stages_head) + "pressure = 100.0\nshear_rate = 1.0\n")
                .find("a cell held at a pressure"),
            std::string::npos);
  EXPECT_EQ(refusal(compress_then_shear), "(not refused)");
}

// The last stage may leave its duration out (it lasts to the run's end); the resolved scenario
// must then read back, as a stage's change reloads it.
TEST(LammpsExportStages, ALastStageWithoutDurationReadsBack) {
  const Scenario s = load_scenario(compress_then_shear, "cell_stages.toml");
  const Scenario again = load_scenario(to_toml(s), "again.toml", s.stages[1].set);
  EXPECT_EQ(again.drivers[0].shear_rate, 2.0);
  EXPECT_EQ(again.stages.size(), 2u);
  EXPECT_EQ(again.stages[1].duration, 0.0);
}

} // namespace
} // namespace talus
