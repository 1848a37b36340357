// The check for contacts too soft for the grains' weight (scenario/soft_contacts.hpp): the
// undamped impact overlap of the closed form, and a suggestion that meets its aim.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <fmt/core.h>

#include "scenario/file/load.hpp"
#include "scenario/soft_contacts.hpp"

namespace talus {
namespace {

BuiltScenario built(const std::string& shape, const std::vector<std::string>& set = {}) {
  const std::string text = "[[materials]]\nname = \"grain\"\n[particles]\ncount = 20\nshape = \"" +
                           shape +
                           "\"\nsize = { mean_radius = 0.002, spread = 0.0 }\n"
                           "[packing]\nmethod = \"lattice\"\nsettle_max_time = 0.0\n"
                           "[geometry]\nbuilder = \"box\"\nwidth = 0.05\nheight = 0.05\n";
  return build_scenario(load_scenario(text, "soft.toml", set));
}

// A disk of radius 2 mm, 1 m thick, of the default density (0.0333 kg) against the default
// 1e5 N/m: against a wall at 1 m/s the linear law's undamped peak overlap is v sqrt(m / k) (the
// closed form of a harmonic half-period), 29% of the radius; a sphere of that radius overlaps
// 1.5%.
TEST(SoftContacts, AHeavyDiskOnTheDefaultStiffnessIsWarnedOfWithWhatFits) {
  const BuiltScenario disk = built("disk");
  const double m = Material{}.density * std::numbers::pi * 0.002 * 0.002; // 1 m thick
  const SoftContact c = softest_contact(disk);
  EXPECT_TRUE(c.wall);
  EXPECT_NEAR(c.mass, m, 1e-12 * m);
  EXPECT_NEAR(c.overlap, std::sqrt(m / 1e5), 1e-12);
  const Scenario s = load_scenario("[[materials]]\nname = \"grain\"\n", "soft.toml");
  const std::string w = soft_contact_warning(s, disk);
  EXPECT_NE(w.find("materials.0.normal_stiffness = 1e+05 N/m lets a grain of 0.0333 kg"),
            std::string::npos)
      << w;
  // the stiffness it names keeps the overlap to 5%, to rounding
  const double fit = 1e5 * std::pow(c.fraction / 0.05, 2.0);
  EXPECT_NE(w.find("keeps that to 5%"), std::string::npos) << w;
  const SoftContact after =
      softest_contact(built("disk", {fmt::format("materials.0.normal_stiffness={:.17g}", fit)}));
  EXPECT_NEAR(after.fraction, 0.05, 1e-9);
  EXPECT_TRUE(soft_contact_warning(s, built("sphere")).empty());
}

} // namespace
} // namespace talus
