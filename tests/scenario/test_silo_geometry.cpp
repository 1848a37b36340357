// The flat-bottomed silo with an orifice: its walls, its keys' errors, and a short discharge.
#include <gtest/gtest.h>

#include <cmath>

#include "post/discharge.hpp"
#include "scenario/build.hpp"
#include "scenario/file/load.hpp"
#include "scenario/geometry.hpp"
#include "support/builtin_scenario.hpp"

namespace talus {
namespace {

GeometrySection silo(double orifice, std::optional<double> x = std::nullopt) {
  GeometrySection g;
  g.builder = "silo";
  g.width = 0.4, g.height = 0.6, g.orifice = orifice, g.orifice_x = x;
  return g;
}

std::string error_of(const std::string& geometry) {
  try {
    build_container(
        load_scenario("[geometry]\nbuilder = \"silo\"\nwidth = 0.4\nheight = 0.6\n" + geometry,
                      "t.toml")
            .geometry);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

TEST(FlatSilo, FloorHasTheOrificeAndABinCatchesWhatFlowsOut) {
  const ContainerShape c = build_container(silo(0.06));
  const auto& floor = c.groups.at("floor");
  ASSERT_EQ(floor.size(), 2u);
  EXPECT_DOUBLE_EQ(floor[0].b.x, 0.17);
  EXPECT_DOUBLE_EQ(floor[1].a.x, 0.23);
  ASSERT_EQ(c.gate.size(), 1u); // closed while the grains settle
  EXPECT_DOUBLE_EQ(c.gate[0].a.x, 0.17);
  EXPECT_DOUBLE_EQ(c.gate[0].b.x, 0.23);
  EXPECT_EQ(c.groups.at("lower").size(), 3u); // the bin: two sides and its floor
  EXPECT_DOUBLE_EQ(c.bounds.lo.y, -0.6);      // as deep as the silo is high, by default
  EXPECT_DOUBLE_EQ(c.fill.lo.y, 0.0);
  EXPECT_TRUE(has_orifice(silo(0.06)));
  EXPECT_FALSE(has_orifice(silo(0.0))); // no orifice: the closed silo of silo_shake
  EXPECT_EQ(build_container(silo(0.0)).groups.at("floor").size(), 1u);
}

TEST(FlatSilo, OrificeMayBeOffCentreOrAgainstAWall) {
  const auto [x0, x1] = orifice_span(silo(0.06, 0.1));
  EXPECT_DOUBLE_EQ(x0, 0.07);
  EXPECT_DOUBLE_EQ(x1, 0.13);
  // against the left wall: one floor piece, to the right of the orifice
  const ContainerShape c = build_container(silo(0.06, 0.03));
  ASSERT_EQ(c.groups.at("floor").size(), 1u);
  EXPECT_DOUBLE_EQ(c.groups.at("floor")[0].a.x, 0.06);
}

TEST(FlatSilo, BadKeysAreNamedWithWhatIsAllowed) {
  EXPECT_NE(error_of("orifice = 0.06\norifice_x = 0.38\n").find("geometry.orifice_x"),
            std::string::npos);
  EXPECT_NE(error_of("orifice = 0.4\n").find("0 < orifice < width"), std::string::npos);
  EXPECT_NE(error_of("bin_depth = 0.2\n").find("geometry.bin_depth"), std::string::npos)
      << "a bin needs an orifice";
  EXPECT_NE(error_of("orifice = 0.06\nbin_depth = 0\n").find("bin_depth > 0"), std::string::npos);
  // a hopper's wall angle of 0 points to the flat silo
  try {
    load_scenario("[geometry]\nbuilder = \"hopper\"\nwall_angle = 0\n", "t.toml");
    FAIL() << "accepted";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("builder = \"silo\""), std::string::npos) << e.what();
  }
}

TEST(FlatSilo, ResolvedScenarioKeepsTheOrificeKeys) {
  Scenario s =
      testing::builtin("silo_discharge", {"geometry.orifice_x=0.1", "geometry.bin_depth=0.3"});
  const Scenario back = load_scenario(to_toml(s), "resolved.toml");
  EXPECT_EQ(back.geometry.orifice_x, 0.1);
  EXPECT_EQ(back.geometry.bin_depth, 0.3);
}

// A small silo_discharge: grains leave through the orifice at a steady rate and stay in the bin.
TEST(FlatSilo, GrainsDischargeThroughTheOrificeIntoTheBin) {
  const Scenario s = testing::builtin(
      "silo_discharge", {"particles.count=200", "geometry.width=0.15", "geometry.height=0.3",
                         "simulation.duration=0.3", "packing.settle_max_time=0.4"});
  BuiltScenario b = build_scenario(s);
  Simulation sim(std::move(b.world), b.config);
  std::vector<Frame> frames{frame_of(sim)};
  const auto every = static_cast<std::uint64_t>(std::llround(0.01 / b.config.timestep));
  const auto total = static_cast<std::uint64_t>(std::ceil(0.3 / b.config.timestep));
  for (std::uint64_t k = 1; k <= total; ++k) {
    sim.step();
    if (k % every == 0) frames.push_back(frame_of(sim));
  }
  const auto [x0, x1] = orifice_span(s.geometry);
  const Discharge q = discharge(frames, Orifice{0.0, x0, x1});
  // a 6 d orifice passes some 80 of the 200 grains in 0.3 s (Beverloo: about 300 grains/s);
  // the bounds are loose, for the flow of a few grains is chaotic
  EXPECT_GT(q.passed, 40u);
  EXPECT_TRUE(q.why_no_rate.empty()) << q.why_no_rate;
  EXPECT_GT(q.rate, 100.0);
  EXPECT_LT(q.rate, 800.0);
  for (const Vec2 r : frames.back().position) EXPECT_GT(r.y, -0.3) << "a grain left the bin";
}

} // namespace
} // namespace talus
