// Decks as LAMMPS users write them: pair_style hybrid beside the walls, repeated keys,
// pair_modify mix, units other than SI, a timestep too coarse for the contacts; and errors that
// cite the line that found the problem.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "lammps_instance.hpp"

namespace talus::lammps_test {
namespace {

const std::string linear = "pair_style granthesis linear coulomb";

TEST(DeckChecks, RepeatedKeysAreRefused) {
  expect_deck_error(two_type_deck({linear, "pair_coeff * * young 1e9 young 2e9"}),
                    "pair_coeff: key 'young' is given twice; allowed: each key once");
  expect_deck_error(
      two_type_deck({"pair_style granthesis hertz coulomb impact_speed 1 impact_speed 2"}),
      "keyword 'impact_speed' is given twice");
  expect_deck_error({"dimension 2", "units si", "atom_style sphere", "boundary f f p",
                     "region box block -1 1 -1 1 -0.01 0.01", "create_box 1 box",
                     "fix f all frost/heave epsilon 1e-6 factor 1.5 table 0 factor 2"},
                    "keyword 'factor' is given twice");
}

TEST(DeckChecks, PairModifyMixIsRefusedAndOtherKeywordsPass) {
  expect_deck_error(two_type_deck({linear, "pair_coeff * *", "pair_modify mix arithmetic"}),
                    "pair_modify mix would have no effect");
  int status = 0;
  const std::string printed =
      run_deck(two_type_deck({linear, "pair_coeff * *", "pair_modify shift no", "run 0"}), status);
  EXPECT_EQ(status, 0) << printed;
}

// Every value and default of the styles is in SI; other units are refused, not converted.
TEST(DeckChecks, UnitsOtherThanSiAreRefused) {
  for (const char* units : {"cgs", "micro", "lj"})
    expect_deck_error({"dimension 2", std::string("units ") + units, "atom_style sphere",
                       "boundary f f p", "comm_modify vel yes",
                       "region box block -1 1 -1 1 -0.01 0.01", "create_box 1 box",
                       "create_atoms 1 single 0 0 0", linear, "pair_coeff * *", "run 0"},
                      std::string("units ") + units + ": every value of the talus styles");
  expect_deck_error({"dimension 2", "units cgs", "atom_style sphere", "boundary f f p",
                     "region box block -1 1 -1 1 -0.01 0.01", "create_box 1 box",
                     "create_atoms 1 single 0 0 0",
                     "fix f all frost/heave epsilon 1e-6 factor 1.5 table 0", "run 0"},
                    "allowed: units si");
}

// The file and line LAMMPS prints after an error: the place that found the problem, so two
// different problems cite two different lines.
std::string cited_place(const std::string& printed) {
  std::smatch m;
  if (!std::regex_search(printed, m, std::regex(R"(ERROR[^\n]*\(([^()\n]+\.cpp:[0-9]+)\))")))
    return "none";
  return m[1];
}

TEST(DeckChecks, ErrorsCiteTheLineThatFoundTheProblem) {
  const std::string law = cited_place(
      expect_deck_error(two_type_deck({"pair_style granthesis hooke coulomb"}), "hooke"));
  const std::string coeff = cited_place(expect_deck_error(
      two_type_deck({linear, "pair_coeff 1 1", "run 0"}), "no pair_coeff for type 2"));
  EXPECT_NE(law.find("pair_granthesis.cpp:"), std::string::npos) << law;
  EXPECT_NE(coeff.find("pair_granthesis.cpp:"), std::string::npos) << coeff;
  EXPECT_NE(law, coeff);
}

// Disks of types 1 and 2 falling on a floor of segment type 2; type 2's grain pairs are given
// to LAMMPS' gran/hooke. Prints the heights of atoms 1 and 2 at the end.
std::vector<std::string> hybrid_deck(const std::string& style,
                                     const std::vector<std::string>& coeffs) {
  std::vector<std::string> deck{"dimension 2",
                                "units si",
                                "atom_style sphere",
                                "atom_modify map array",
                                "boundary f f p",
                                "comm_modify vel yes",
                                "newton off",
                                "region box block 0 0.1 -0.01 0.2 -0.01 0.01",
                                "create_box 2 box",
                                "create_atoms 1 single 0.02 0.02 0",
                                "create_atoms 2 single 0.05 0.02 0",
                                "set atom * diameter 0.01",
                                "set atom * density/disc 2650",
                                "pair_style " + style +
                                    " granthesis linear coulomb gran/hooke 1e4 NULL 10 NULL 0.5 0"};
  deck.insert(deck.end(), coeffs.begin(), coeffs.end());
  deck.insert(deck.end(),
              {"pair_coeff 2 2 gran/hooke", "fix gravity all gravity 9.81 vector 0 -1 0",
               "fix floor all granthesis/wall segment 0 0 0.1 0 type 2",
               "fix move all nve/sphere disc", "fix plane all enforce2d", "timestep 1e-5",
               "run 20000", "variable y1 equal y[1]", "variable y2 equal y[2]",
               "print \"HEIGHTS ${y1} ${y2}\""});
  return deck;
}

// Under pair_style hybrid the walls act on every type with granthesis' laws and the type's
// granthesis material: the grains of both types come to rest on the floor, at a height of their
// radius less the overlap of their weight (k = 1e4 N/m: 0.2 mm).
TEST(DeckChecks, HybridGrainsRestOnTheWalls) {
  int status = 0;
  const std::string printed = run_deck(
      hybrid_deck("hybrid", {"pair_coeff * * granthesis normal_stiffness 1e4 restitution 0.5"}),
      status);
  ASSERT_EQ(status, 0) << printed;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(printed, m, std::regex(R"(HEIGHTS (\S+) (\S+))"))) << printed;
  for (const std::string& height : {m[1].str(), m[2].str()}) {
    EXPECT_GT(std::stod(height), 0.0045) << printed;
    EXPECT_LT(std::stod(height), 0.005) << printed;
  }
}

TEST(DeckChecks, HybridTypesWithoutAMaterialAndOverlaysAreRefused) {
  expect_deck_error(hybrid_deck("hybrid", {"pair_coeff 1 1 granthesis normal_stiffness 1e4",
                                           "pair_coeff 1 2 gran/hooke"}),
                    "touches segment 1 of type 2, but type 2 has no granthesis material");
  expect_deck_error(hybrid_deck("hybrid/overlay", {"pair_coeff * * granthesis"}),
                    "pair_style hybrid/overlay adds the forces of gran/hooke and granthesis");
}

// k = 1e4 N/m, 5 mm disks of 2650 kg/m^2: a collision lasts about 10 ms between two grains and
// 15 ms against a wall; 3 ms resolves it in fewer steps than is safe.
TEST(DeckChecks, ATimestepTooCoarseForTheContactsIsWarnedOf) {
  const std::vector<std::string> lines{
      linear, "pair_coeff * * normal_stiffness 1e4",
      "fix floor all granthesis/wall segment -1 -0.005 1 -0.005 type 1",
      "fix move all nve/sphere disc"};
  std::vector<std::string> coarse = lines, fine = lines;
  coarse.insert(coarse.end(), {"timestep 3e-3", "run 1"});
  fine.insert(fine.end(), {"timestep 1e-4", "run 1"});
  expect_deck_warning(two_type_deck(coarse),
                      "pair granthesis: the timestep 0.003 s resolves the collision of two "
                      "grains of types 1 and 1");
  expect_deck_warning(two_type_deck(coarse), "fix granthesis/wall: the timestep 0.003 s");
  int status = 0;
  const std::string printed = run_deck(two_type_deck(fine), status);
  EXPECT_EQ(status, 0) << printed;
  EXPECT_EQ(printed.find("resolves the collision"), std::string::npos) << printed;
}

} // namespace
} // namespace talus::lammps_test
