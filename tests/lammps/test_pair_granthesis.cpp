// pair_style granthesis in LAMMPS: the errors of bad input (test_pair_laws.cpp has the physics).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "atom.h"
#include "fix.h"
#include "force.h"
#include "lammps_instance.hpp"
#include "modify.h"
#include "pair.h"

namespace talus::lammps_test {
namespace {

// Two types of disks in a box, then `lines`: an error naming `expected` (run_deck).
void expect_error(const std::vector<std::string>& lines, const std::string& expected) {
  expect_deck_error(two_type_deck(lines), expected);
}

TEST(PairGranthesis, BadInputNamesTheSettingAndTheAllowedValues) {
  expect_error({"pair_style granthesis"}, "NORMAL: linear, hertz");
  expect_error({"pair_style granthesis hooke coulomb"}, "unknown normal law 'hooke'");
  expect_error({"pair_style granthesis linear stick"}, "allowed: coulomb, cundall_strack");
  expect_error({"pair_style granthesis linear cundall_strack", "pair_coeff * *", "run 0"},
               "needs newton_pair off (newton off");
  expect_error({"pair_style granthesis linear coulomb history_slots 0"},
               "K: the contacts an atom may have at once");
  expect_error({"pair_style granthesis linear coulomb", "pair_coeff 1 1 stiffness 1e5"},
               "unknown key 'stiffness'; allowed: young, poisson");
  expect_error({"pair_style granthesis linear coulomb", "pair_coeff 1 1 friction -0.1"},
               "friction = -0.1; allowed: >= 0");
  expect_error({"pair_style granthesis linear coulomb", "pair_coeff 1 1 friction nan"},
               "friction = 'nan' is not a finite number");
  expect_error({"pair_style granthesis linear coulomb", "pair_coeff 1 1 young"},
               "young: the value is missing");
  expect_error({"pair_style granthesis linear coulomb", "pair_coeff 1 1 density 2650"},
               "density/disc");
  expect_error({"pair_style granthesis linear coulomb", "pair_coeff 1 1", "run 0"},
               "no pair_coeff for type 2");
  expect_error({"pair_style granthesis hertz coulomb impact_speed -1"},
               "impact_speed = -1 (usage: pair_style granthesis NORMAL TANGENTIAL [impact_speed V] "
               "[history_slots K] [inertia disc|sphere]; NORMAL: linear, hertz");
  expect_error({"pair_style granthesis hertz coulomb inertia rod"},
               "inertia = rod (usage: pair_style granthesis");
  expect_error({"newton on", "pair_style granthesis linear coulomb",
                "pair_coeff * * rolling_friction 0.1", "run 0"},
               "rolling resistance (rolling_friction > 0) keeps a spring per contact, which needs "
               "newton_pair off");
  expect_error({"pair_style granthesis hertz coulomb speed 1"}, "V: the impact speed (m/s, > 0");
  expect_error(
      {"comm_modify vel no", "pair_style granthesis linear coulomb", "pair_coeff * *", "run 0"},
      "comm_modify vel yes");
}

TEST(FixGranthesisWall, BadInputNamesTheSettingAndTheAllowedValues) {
  const std::string pair = "pair_style granthesis linear coulomb";
  expect_error({pair, "pair_coeff * *", "fix w all granthesis/wall"}, "no segment given");
  expect_error({pair, "pair_coeff * *", "fix w all granthesis/wall segment 0 0 1"},
               "BY is missing");
  expect_error({pair, "pair_coeff * *", "fix w all granthesis/wall segment 0 0 1 0"},
               "'type T' must follow its end points");
  expect_error({pair, "pair_coeff * *", "fix w all granthesis/wall segment 0 0 1 nan type 1"},
               "BY = nan; allowed: a finite number");
  expect_error(
      {pair, "pair_coeff * *", "fix w all granthesis/wall segment 0 0 1 0 type 3", "run 0"},
      "type 3 does not exist; allowed: 1 to 2");
  expect_error({pair, "pair_coeff * *",
                "fix w all granthesis/wall segment 0 0 1 0 type 1 velocity 1 0 rotate 0 0 1"},
               "segment 1 is given a second motion (rotate); allowed: one motion per segment");
  expect_error({pair, "pair_coeff * *",
                "fix w all granthesis/wall segment 0 0 1 0 type 1 vibrate 0 0 0.001 10 0"},
               "segment 1: vibrate DX DY = 0 0; allowed: a direction, not zero");
  expect_error({pair, "pair_coeff * *",
                "fix w all granthesis/wall segment 0 0 1 0 type 1 vibrate 0 1 -0.001 10 0"},
               "vibrate AMPLITUDE -0.001 FREQUENCY 10; allowed: both >= 0 (m, Hz)");
  expect_error({pair, "pair_coeff * *",
                "fix w all granthesis/wall segment 0 0 1 0 type 1 vibrate 0 1 0.001 10"},
               "PHASE is missing");
  expect_error({pair, "pair_coeff * *", "fix w all granthesis/wall wall 0 0 1 0"},
               "unknown keyword 'wall'; allowed: segment, velocity, rotate, vibrate");
  expect_error({"pair_style zero 0.01", "pair_coeff * *",
                "fix w all granthesis/wall segment 0 0 1 0 type 1", "run 0"},
               "needs pair_style granthesis");
}

// The per-atom vector of fix granthesis/wall counts each atom's wall contacts as the native
// engine does: a face is one contact, the shared end point of two segments one, not two.
TEST(FixGranthesisWall, CountsEachAtomsWallContactsAsTheNativeEngine) {
  LammpsInstance lammps;
  lammps.commands({"dimension 2", "units si", "atom_style sphere", "atom_modify map array",
                   "boundary f f p", "comm_modify vel yes", "region box block -1 1 -1 1 -0.01 0.01",
                   "create_box 2 box",
                   // on a floor; above the valley of a V (both arms' faces); on the peak of an
                   // inverted V (the shared end point only); in the air
                   "create_atoms 1 single -0.5 0.004 0", "create_atoms 1 single 0.3 0.004 0",
                   "create_atoms 1 single 0.6 0.104 0", "create_atoms 1 single -0.5 0.5 0",
                   "set atom * diameter 0.01", "set atom * density/disc 2650",
                   "pair_style granthesis linear coulomb", "pair_coeff * * normal_stiffness 1e4",
                   "fix w all granthesis/wall segment -1 0 0 0 type 2 segment 0.2 0.1 0.3 0 type 2 "
                   "segment 0.3 0 0.4 0.1 type 2 segment 0.5 0 0.6 0.1 type 2 segment 0.6 0.1 0.7 "
                   "0 type 2",
                   "fix integrate all nve/sphere disc", "run 0"});
  LAMMPS_NS::Modify* modify = lammps.lmp()->modify;
  const double* count = modify->fix[modify->find_fix("w")]->vector_atom;
  ASSERT_NE(count, nullptr);
  EXPECT_EQ(count[lammps.index(1)], 1.0);
  EXPECT_EQ(count[lammps.index(2)], 2.0);
  EXPECT_EQ(count[lammps.index(3)], 1.0);
  EXPECT_EQ(count[lammps.index(4)], 0.0);
}

// Grains that fix pour inserts into an empty box: the pair's reach covers them from the start
// (LAMMPS' own granular styles read fix pour's largest radius too), so they pile up instead of
// passing through each other on a reach of 0.
TEST(PairGranthesis, FixPourGrainsTouchFromTheStart) {
  LammpsInstance lammps;
  lammps.commands(
      {"dimension 2", "units si", "atom_style sphere", "boundary f f p", "comm_modify vel yes",
       "region box block 0 0.1 0 0.3 -0.01 0.01", "create_box 1 box",
       "pair_style granthesis linear coulomb",
       "pair_coeff * * normal_stiffness 1e3 restitution 0.3 friction 0.5 tangential_damping 500",
       "region ins block 0.005 0.095 0.1 0.29 -0.01 0.01",
       "fix gravity all gravity 9.81 vector 0 -1 0",
       "fix ins all pour 40 1 4767 region ins diam range 0.008 0.012 vel 0 0 0",
       "fix floor all granthesis/wall segment 0 0 0.1 0 type 1 segment 0 0 0 0.3 type 1 segment "
       "0.1 0 0.1 0.3 type 1",
       "fix move all nve/sphere disc", "fix plane all enforce2d", "timestep 1e-5", "run 30000"});
  LAMMPS_NS::LAMMPS* lmp = lammps.lmp();
  EXPECT_GE(lmp->force->pair->cutforce, 0.012) << "the reach of the largest grain to be poured";
  const int n = lmp->atom->nlocal;
  ASSERT_GE(n, 30); // fix pour places what fits in its region without overlaps
  // every pair of grains at rest on the floor apart by at least 0.9 of their radii' sum: on a
  // reach of 0 they would lie through each other
  double** x = lmp->atom->x;
  const double* r = lmp->atom->radius;
  double closest = 1.0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      closest = std::min(closest, std::hypot(x[i][0] - x[j][0], x[i][1] - x[j][1]) / (r[i] + r[j]));
  EXPECT_GT(closest, 0.9);
}

} // namespace
} // namespace talus::lammps_test
