// fix frost/heave: the thesis' freeze (chapter 5.2.1) in LAMMPS. Heights above the table are
// multiplied by exactly the factor when the group's kinetic energy is below epsilon, and only
// then; in 3d along z, where spheres on a plate settle, heave and settle again; bad fix lines
// stop with their errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "fix.h"
#include "lammps_instance.hpp"
#include "modify.h"

namespace talus::lammps_test {
namespace {

constexpr double table = 0.01, factor = 1.5;
const double heights[3] = {0.02, 0.0537, 0.11}; // m, far apart: no contacts

// Three disks at rest above the table, stepped by fix nve/sphere, with `fix_line`.
void set_up(LammpsInstance& l, const std::string& fix_line) {
  l.commands({"dimension 2", "units si", "atom_style sphere", "atom_modify map array",
              "boundary f f p", "comm_modify vel yes", "region box block -1 1 -1 1 -0.01 0.01",
              "create_box 1 box"});
  for (int k = 0; k < 3; ++k)
    l.command("create_atoms 1 single " + exact(0.1 * k) + " " + exact(heights[k]) + " 0");
  l.commands({"set atom * diameter 0.01", "set atom * density/disc 2650",
              "pair_style granthesis linear coulomb", "pair_coeff * *",
              "fix move all nve/sphere disc", "fix plane all enforce2d", fix_line,
              "timestep 1e-6"});
}

double heaves(LammpsInstance& l) {
  LAMMPS_NS::Modify* m = l.lmp()->modify;
  return m->fix[m->find_fix("frost")]->compute_scalar();
}

TEST(FixFrostHeave, LiftsHeightsAboveTheTableByExactlyTheFactor) {
  LammpsInstance l;
  set_up(l, "fix frost all frost/heave epsilon 1e-12 factor 1.5 table 0.01 interval 1");
  l.command("run 1"); // at rest: the first step's end heaves
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(l.position(k + 1)[1], table + (heights[k] - table) * factor);
    EXPECT_EQ(l.position(k + 1)[0], 0.1 * k);
  }
  EXPECT_EQ(heaves(l), 1.0);
  l.command("run 100"); // still at rest, but within the interval of 1 s: no second heave
  EXPECT_EQ(heaves(l), 1.0);
  EXPECT_EQ(l.position(1)[1], table + (heights[0] - table) * factor);
}

// 1/2 m v^2 of one disk of 5 mm (2650 kg/m^3, a disk: m = 0.208 kg) at 0.01 m/s is about 1e-5 J,
// above the epsilon of 1e-6 J: no heave while it moves, one as soon as it stops.
TEST(FixFrostHeave, HeavesOnlyBelowTheThreshold) {
  LammpsInstance l;
  set_up(l, "fix frost all frost/heave epsilon 1e-6 factor 1.5 table 0.01");
  l.command("set atom 2 vx 0.01");
  l.command("run 20");
  EXPECT_EQ(heaves(l), 0.0);
  EXPECT_EQ(l.position(1)[1], heights[0]);
  l.command("velocity all set 0 0 0");
  l.command("run 1");
  EXPECT_EQ(heaves(l), 1.0);
  EXPECT_EQ(l.position(1)[1], table + (heights[0] - table) * factor);
}

// initial_wait yes: the interval counts from the fix's definition too (the native rule: a cycle
// waits min_interval from the start), so grains at rest heave only once it has passed.
TEST(FixFrostHeave, InitialWaitCountsTheIntervalFromTheStart) {
  LammpsInstance l;
  set_up(l, "fix frost all frost/heave epsilon 1e-12 factor 1.5 table 0.01 interval 5e-5 "
            "initial_wait yes");
  l.command("run 49"); // 49 steps, short of the interval of 50: no heave yet, though at rest
  EXPECT_EQ(heaves(l), 0.0);
  EXPECT_EQ(l.position(1)[1], heights[0]);
  l.command("run 2"); // 50 x 1e-6 may round below 5e-5: the heave comes at step 50 or 51

  EXPECT_EQ(heaves(l), 1.0);
  EXPECT_EQ(l.position(1)[1], table + (heights[0] - table) * factor);
}

// In 3d the heave is along z, gravity's axis: spheres at rest in the air are lifted by exactly
// the factor above the table, their x and y unchanged.
TEST(FixFrostHeave, LiftsAlongZIn3d) {
  LammpsInstance l;
  l.commands({"dimension 3", "units si", "atom_style sphere", "atom_modify map array",
              "boundary f f f", "comm_modify vel yes",
              "region box block -0.5 0.5 -0.5 0.5 -0.5 0.5", "create_box 1 box"});
  for (int k = 0; k < 3; ++k)
    l.command("create_atoms 1 single " + exact(0.1 * k) + " 0.03 " + exact(heights[k]));
  l.commands({"set atom * diameter 0.01", "set atom * density 2650",
              "pair_style granthesis linear coulomb", "pair_coeff * *", "fix move all nve/sphere",
              "fix frost all frost/heave epsilon 1e-12 factor 1.5 table 0.01", "timestep 1e-6",
              "run 1"});
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(l.position(k + 1)[2], table + (heights[k] - table) * factor);
    EXPECT_EQ(l.position(k + 1)[0], 0.1 * k);
    EXPECT_EQ(l.position(k + 1)[1], 0.03);
  }
  EXPECT_EQ(heaves(l), 1.0);
}

// A column of three spheres on a plate (fix granthesis/wall) comes to rest, is heaved, falls
// back and comes to rest again: the freeze-thaw cycle of the thesis along gravity in 3d. Each
// heave lifts the top sphere by (factor - 1) times its height above the floor, and after it
// the column stands where it stood (the spheres stack straight above each other).
TEST(FixFrostHeave, SpheresOnAPlateSettleHeaveAndSettleAgainIn3d) {
  LammpsInstance l;
  l.commands({"dimension 3",
              "units si",
              "atom_style sphere",
              "atom_modify map array",
              "boundary f f f",
              "comm_modify vel yes",
              "region box block -0.1 0.1 -0.1 0.1 -0.1 0.3",
              "create_box 1 box",
              "create_atoms 1 single 0 0 0.0052",
              "create_atoms 1 single 0 0 0.0154",
              "create_atoms 1 single 0 0 0.0256",
              "set atom * diameter 0.01",
              "set atom * density 2650",
              "pair_style granthesis linear coulomb",
              "pair_coeff * * normal_stiffness 1e5 restitution 0.3",
              "neighbor 0.002 bin",
              "fix move all nve/sphere",
              "fix gravity all gravity 9.81 vector 0 0 -1",
              "fix floor all granthesis/wall plane 0 0 0 0 0 1 type 1",
              "fix frost all frost/heave epsilon 1e-9 factor 1.2 table 0 interval 0.05",
              "timestep 2e-6"});
  // in runs of 1 ms: a heaved sphere falls 5 um in the first
  double highest = 0.0;
  for (int k = 0; k < 1000 && heaves(l) < 2.0; ++k) {
    l.command("run 500");
    highest = std::max(highest, l.position(3)[2]);
  }
  EXPECT_EQ(heaves(l), 2.0);
  // the top sphere at rest sits near 2.5 diameters less its contacts' overlaps; heaved by a
  // fifth of that, less what it falls in the first millisecond
  EXPECT_GT(highest, 1.2 * 0.0249 - 1e-5);
  l.command("run 20000"); // it falls back onto the column
  EXPECT_NEAR(l.position(3)[2], 0.025, 2e-4);
  EXPECT_NEAR(l.position(3)[0], 0.0, 1e-9);
}

void expect_error(const std::string& fix_line, const std::string& expected) {
  expect_deck_error({"dimension 2", "units si", "atom_style sphere", "boundary f f p",
                     "region box block -1 1 -1 1 -0.01 0.01", "create_box 1 box",
                     "create_atoms 1 single 0 0 0", fix_line},
                    expected);
}

TEST(FixFrostHeave, BadLinesNameTheKeywordAndTheAllowedValues) {
  expect_error("fix f all frost/heave factor 1.5 table 0",
               "epsilon, factor and table are required");
  expect_error("fix f all frost/heave epsilon -1 factor 1.5 table 0",
               "epsilon = -1; allowed: >= 0 J");
  expect_error("fix f all frost/heave epsilon 1e-6 factor 0 table 0", "factor = 0; allowed: > 0");
  expect_error("fix f all frost/heave epsilon 1e-6 factor inf table 0", "factor = inf");
  expect_error("fix f all frost/heave epsilon 1e-6 factor 1.5 table 0 initial_wait maybe",
               "initial_wait = maybe; allowed: yes, no");
  expect_error("fix f all frost/heave epsilon 1e-6 factor 1.5 table 0 every 2.5",
               "every = 2.5; allowed: an integer >= 1");
  expect_error("fix f all frost/heave epsilon 1e-6 factor 1.5 table 0 inertia cube",
               "inertia = cube; allowed: disc, sphere");
  expect_error("fix f all frost/heave epsilon 1e-6 factor 1.5 table 0 delta 2",
               "unknown keyword 'delta'");
  expect_error("fix f all frost/heave epsilon 1e-6 factor 1.5 table",
               "table: the value is missing");
}

} // namespace
} // namespace talus::lammps_test
