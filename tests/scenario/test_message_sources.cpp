// Every refusal names where the bad value came from: the file and line, the --set, or the thesis
// .in file's own line (never the line of a scenario converted behind the user's back).
#include <gtest/gtest.h>

#include "io/thesis_format.hpp"
#include "scenario/build.hpp"
#include "scenario/file/load.hpp"
#include "talus/error.hpp"

namespace talus {
namespace {

template <class F> std::string refusal(F&& f) {
  try {
    f();
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "(accepted)";
}

const std::string three_grains = "0.01 0.02 0 0.1 0 0 0.001 0.002 0 0.5 0.01 10000 50\n"
                                 "0.02 0.02 0 -0.1 0 0 0.001 0.002 0 0.5 0.01 10000 50\n"
                                 "0.0 0.0 0 0 0 0 0.001 0.002 1 0.5 0.01 10000 50\n";

std::string thesis_refusal(const std::string& text) {
  return refusal([&] {
    const ThesisFile f = read_thesis_in(text, "y0.in");
    load_scenario(to_toml(scenario_from_thesis(f, "y0")), "y0.in (converted)");
  });
}

TEST(MessageSources, ThesisFilesNameTheirOwnLines) {
  const std::string head = "1\n0.5\n1e-06\n0 -9.81 0\n";
  EXPECT_EQ(thesis_refusal("3\n" + head + three_grains), "(accepted)");
  // N a whole number >= 1: 2.5 was read as 2, 0 gave "expected an array of tables"
  for (const char* n : {"2.5", "0", "-1", "three"})
    EXPECT_NE(thesis_refusal(n + ("\n" + head + three_grains))
                  .find("y0.in:1: line 1 must be the number of particles N, a whole number >= 1"),
              std::string::npos)
        << n;
  // a z component of gravity the disks cannot feel is refused, not dropped
  EXPECT_NE(thesis_refusal("3\n1\n0.5\n1e-06\n0 0 -9.81\n" + three_grains)
                .find("y0.in:5: line 5: gravity z = -9.81"),
            std::string::npos);
  // a stiffness out of range names the particle line it came from
  std::string bad = three_grains;
  bad.replace(bad.find("10000 50\n0.02"), 5, "-1000");
  const std::string why = thesis_refusal("3\n" + head + bad);
  EXPECT_NE(why.find("y0.in:6: particle line"), std::string::npos) << why;
  EXPECT_NE(why.find("normal_stiffness = -1000 is out of range"), std::string::npos) << why;
}

TEST(MessageSources, SetValuesAndReferencesNameTheirSource) {
  const std::string text = "[[materials]]\nname = \"grain\"\n[particles]\ncount = 10\n";
  // a key missing from a table the --set gave
  std::string why = refusal(
      [&] { load_scenario(text, "s.toml", {"particles.size={distribution=\"discrete\"}"}); });
  EXPECT_NE(why.find("--set particles.size={distribution=\"discrete\"}: key "
                     "'particles.size.fractions'"),
            std::string::npos)
      << why;
  // a material named by --set, or by the file
  why = refusal([&] { load_scenario(text, "s.toml", {"particles.material=\"nope\""}); });
  EXPECT_NE(why.find("--set particles.material=\"nope\": key 'particles.material': no material "
                     "named 'nope'"),
            std::string::npos)
      << why;
  why = refusal([&] { load_scenario(text + "material = \"nope\"\n", "s.toml"); });
  EXPECT_NE(why.find("s.toml:5: key 'particles.material'"), std::string::npos) << why;
}

// A key the file leaves out is still a key of its table, for the hint of a misspelt one.
TEST(MessageSources, AnUnknownKeysHintNamesKeysTheFileLeavesOut) {
  const std::string why =
      refusal([] { load_scenario("[simulation]\nduration = 1.0\ntimestepp = 1e-5\n", "h.toml"); });
  EXPECT_NE(why.find("h.toml:3: key 'simulation.timestepp': unknown key; did you mean 'timestep'?"),
            std::string::npos)
      << why;
}

// Every grain fixed, with an explicit timestep: no bare "stiffness and mass must be > 0".
TEST(MessageSources, AScenarioWithNoFreeGrainSaysSo) {
  const Scenario s = load_scenario("[simulation]\ntimestep = 1e-5\n[particles]\nshape = "
                                   "\"sphere\"\n[[particles.list]]\nposition = [0.0, 0.0]\n"
                                   "radius = 0.001\nkind = \"fixed\"\n",
                                   "f.toml");
  const std::string why = refusal([&] { build_scenario(s); });
  EXPECT_NE(why.find("key 'particles.list': every grain's kind is \"fixed\" or \"moved\""),
            std::string::npos)
      << why;
}

} // namespace
} // namespace talus
