// The analyses of snapshots (src/post) on frames built by hand, where the answer is known exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "talus/error.hpp"

#include "post/discharge.hpp"
#include "post/flow_profiles.hpp"
#include "post/frost_cycles.hpp"
#include "post/segregation.hpp"
#include "scenario/file/picture_request.hpp"

namespace talus {
namespace {

void add(Frame& f, std::uint32_t id, Vec2 r, double radius, Vec2 v = {}, std::uint8_t kind = 0) {
  f.id.push_back(id);
  f.position.push_back(r);
  f.radius.push_back(radius);
  f.velocity.push_back(v);
  f.force.push_back({});
  f.kind.push_back(kind);
  f.material.push_back(0);
}

TEST(BandProfile, AveragesVelocitiesPerBinOverFramesAndSkipsWallsAndGrainsOutsideTheBand) {
  std::vector<Frame> frames(2);
  // bins of 0.1 m over [0, 0.3): two samples in bin 0, one in bin 2, none in bin 1
  add(frames[0], 0, {0.05, 0.5}, 0.01, {1.0, -2.0});
  add(frames[1], 0, {0.06, 0.5}, 0.01, {3.0, -4.0});
  add(frames[0], 1, {0.25, 0.55}, 0.01, {0.0, -3.0});
  add(frames[0], 2, {0.15, 0.9}, 0.01, {5.0, 5.0});    // above the band
  add(frames[0], 3, {0.15, 0.5}, 0.01, {5.0, 5.0}, 1); // a wall particle
  const BandProfile p = band_profile(frames, 0.4, 0.6, 0.0, 0.3, 3);
  ASSERT_EQ(p.x.size(), 3u);
  EXPECT_DOUBLE_EQ(p.x[1], 0.15);
  EXPECT_EQ(p.count[0], 2u);
  EXPECT_EQ(p.count[1], 0u);
  EXPECT_DOUBLE_EQ(p.vx[0], 2.0);
  EXPECT_DOUBLE_EQ(p.vy[0], -3.0);
  EXPECT_DOUBLE_EQ(p.speed[0], 0.5 * (std::sqrt(5.0) + 5.0));
  EXPECT_DOUBLE_EQ(p.vy[2], -3.0);
  EXPECT_THROW(band_profile(frames, 0.6, 0.4, 0.0, 0.3, 3), InvalidArgument);
}

TEST(SpeedMap, MeanSpeedPerCell) {
  std::vector<Frame> frames(1);
  add(frames[0], 0, {0.05, 0.05}, 0.01, {3.0, 4.0});
  add(frames[0], 1, {0.06, 0.04}, 0.01, {0.0, 1.0});
  add(frames[0], 2, {0.15, 0.15}, 0.01, {0.0, -2.0});
  const SpeedMap m = speed_map(frames, {{0.0, 0.0}, {0.2, 0.2}}, 0.1);
  ASSERT_EQ(m.nx, 2u);
  ASSERT_EQ(m.ny, 2u);
  EXPECT_EQ(m.count[0], 2u);
  EXPECT_DOUBLE_EQ(m.mean_speed[0], 3.0);
  EXPECT_EQ(m.count[1], 0u);
  EXPECT_DOUBLE_EQ(m.mean_speed[3], 2.0);
}

// Frames every `dt` s, with `count(k)` grains below y = 0 at frame k out of `total`; the rest
// sit at `above` (over the orifice from x = -0.05 to 0.05 when above.x is 0).
std::vector<Frame> flow_frames(int frames, double dt, int total, auto count,
                               Vec2 above = {0.5, 0.1}) {
  std::vector<Frame> out;
  for (int k = 0; k < frames; ++k) {
    Frame f;
    f.time = k * dt;
    const int below = count(k);
    for (int i = 0; i < total; ++i)
      add(f, static_cast<std::uint32_t>(i), i < below ? Vec2{0.0, -0.1} : above, 0.01);
    out.push_back(f);
  }
  return out;
}

const Orifice orifice{0.0, -0.05, 0.05};

TEST(Discharge, ConstantFlowGivesOneRateInBothHalves) {
  // 50 grains per second pass y = 0 from t = 1 s until the 400 have gone (t = 9 s)
  const auto frames =
      flow_frames(21, 1.0, 400, [](int k) { return std::clamp(50 * (k - 1), 0, 400); });
  const Discharge d = discharge(frames, orifice);
  EXPECT_EQ(d.passed, 400u);
  EXPECT_EQ(d.end, FlowEnd::drained); // 11 s without a grain, nothing over the orifice
  EXPECT_TRUE(d.why_no_rate.empty()) << d.why_no_rate;
  EXPECT_NEAR(d.rate, 50.0, 1e-9);
  EXPECT_NEAR(d.rate_first_half, 50.0, 1e-9);
  EXPECT_NEAR(d.rate_second_half, 50.0, 1e-9);
  EXPECT_NEAR(d.rate_error, 0.0, 1e-9); // every block has the same rate
  // the fitted line passes through the data: 0 grains at t = 1 s
  EXPECT_NEAR(d.intercept + d.rate * 1.0, 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(d.window_from, 1.0);
  EXPECT_DOUBLE_EQ(d.window_to, 9.0);
}

TEST(Discharge, SteadyWindowLeavesOutTheStartAndTheFinalDraining) {
  // 2 s at 10 grains/s (the start), 10 s at 100 grains/s, then 8 s at 25 grains/s (the final
  // draining): 20 + 1000 + 200 grains. A window from 10% to 90% of what came through would end
  // at 1098 grains, 3 s into the draining, and give 84 grains/s.
  const auto count = [](int k) {
    const double t = 0.1 * k;
    const double n = t < 2.0    ? 10.0 * t
                     : t < 12.0 ? 20.0 + 100.0 * (t - 2.0)
                                : 1020.0 + 25.0 * std::min(t - 12.0, 8.0);
    return static_cast<int>(std::floor(n + 1e-9));
  };
  const auto frames = flow_frames(241, 0.1, 1220, count);
  const Discharge d = discharge(frames, orifice);
  EXPECT_EQ(d.end, FlowEnd::drained);
  EXPECT_EQ(d.passed, 1220u);
  // the window lies within the steady part, to within one block (about 20 grains, 0.2 s)
  EXPECT_GE(d.window_from, 2.0 - 1e-9);
  EXPECT_LE(d.window_from, 2.5);
  EXPECT_LE(d.window_to, 12.0 + 1e-9);
  EXPECT_GE(d.window_to, 11.5);
  // whole grains only: the rate is 100 to within the rounding of the counts
  EXPECT_NEAR(d.rate, 100.0, 0.5);
  EXPECT_NEAR(d.rate_first_half / d.rate_second_half, 1.0, 0.01);
}

TEST(Discharge, GivenWindowIsFittedAsGiven) {
  const auto frames =
      flow_frames(21, 1.0, 400, [](int k) { return std::clamp(50 * (k - 1), 0, 400); });
  DischargeOptions o;
  o.window = std::pair{2.0, 5.0};
  const Discharge d = discharge(frames, orifice, o);
  EXPECT_TRUE(d.window_given);
  EXPECT_DOUBLE_EQ(d.window_from, 2.0);
  EXPECT_DOUBLE_EQ(d.window_to, 5.0);
  EXPECT_NEAR(d.rate, 50.0, 1e-9);
  o.window = std::pair{2.0, 2.5}; // one snapshot: no fit
  EXPECT_THROW(discharge(frames, orifice, o), InvalidArgument);
}

TEST(Discharge, ClogIsSaidAndNeverReportedAsARate) {
  // 6 grains pass in the first 0.04 s, then an arch holds the other 194 over the orifice
  const auto frames = flow_frames(
      11, 0.01, 200, [](int k) { return std::min(3 * k, 6); }, Vec2{0.0, 0.02});
  const Discharge d = discharge(frames, orifice);
  EXPECT_EQ(d.end, FlowEnd::clogged);
  EXPECT_EQ(d.passed, 6u);
  EXPECT_TRUE(std::isnan(d.rate));
  EXPECT_NE(d.why_no_rate.find("clogged at t = 0.02 s, after 6 grains"), std::string::npos)
      << d.why_no_rate;
  // a window does not turn a clog into a rate
  DischargeOptions o;
  o.window = std::pair{0.0, 0.03};
  EXPECT_TRUE(std::isnan(discharge(frames, orifice, o).rate));
}

TEST(Discharge, TooFewGrainsGiveNoRateAndAFlowGoingOnIsFlowing) {
  const auto frames = flow_frames(11, 0.1, 100, [](int k) { return 3 * k; });
  const Discharge d = discharge(frames, orifice);
  EXPECT_EQ(d.end, FlowEnd::flowing);
  EXPECT_EQ(d.passed, 30u);
  EXPECT_TRUE(std::isnan(d.rate));
  EXPECT_NE(d.why_no_rate.find("only 30 grains came through"), std::string::npos);
}

TEST(Segregation, IndexIsLargeMinusSmallMeanHeightOverBedHeight) {
  Frame f;
  // a column of small grains R = 1 from y = 1 to 9 and one large grain R = 3 on top at y = 12
  for (int k = 0; k < 5; ++k) add(f, static_cast<std::uint32_t>(k), {0.0, 1.0 + 2.0 * k}, 1.0);
  add(f, 9, {0.0, 12.0}, 3.0);
  const SegregationSeries s = segregation({f});
  EXPECT_EQ(s.large_count, 1u);
  ASSERT_EQ(s.largest.front(), 9u);
  // bottom 0; the top is the 98th percentile of y + R (nearest rank): the largest of six, 15
  EXPECT_DOUBLE_EQ(s.bed_height[0], 15.0);
  EXPECT_DOUBLE_EQ(s.index[0], (12.0 - 5.0) / 15.0);
  EXPECT_DOUBLE_EQ(s.largest_height[0][0], 12.0);
  EXPECT_DOUBLE_EQ(s.largest_depth_fraction[0], 0.0);
}

TEST(Convection, SmallGrainsDownByTheWallsUpInTheMiddle) {
  Frame a, b;
  a.time = 0.0, b.time = 0.5;
  const double x[3] = {0.1, 0.5, 0.9};
  const double dy[3] = {-0.1, 0.2, -0.1};
  for (std::uint32_t i = 0; i < 3; ++i) {
    add(a, i, {x[i], 0.5}, 0.1);
    add(b, i, {x[i], 0.5 + dy[i]}, 0.1);
  }
  add(a, 7, {0.5, 0.2}, 0.5); // a large grain: left out of the drift
  add(b, 7, {0.5, 0.9}, 0.5);
  const ConvectionProfile c = convection({a, b}, 0.3, 3);
  ASSERT_EQ(c.drift.size(), 3u);
  EXPECT_DOUBLE_EQ(c.drift[0], -0.2);
  EXPECT_DOUBLE_EQ(c.drift[1], 0.4);
  EXPECT_DOUBLE_EQ(c.drift[2], -0.2);
}

TEST(FrostCycles, StoneHeightJustBeforeEachFreezeAndItsRisePerCycle) {
  // snapshots every 0.01 s; freezes at 0.05 and 0.10 s lift the stone by 1 mm each
  std::vector<Frame> frames;
  for (int k = 0; k <= 12; ++k) {
    Frame f;
    f.time = 0.01 * k;
    for (std::uint32_t i = 0; i < 10; ++i) add(f, i, {0.001 * i, 0.001}, 0.001);
    const double lift = f.time >= 0.1 - 1e-12 ? 2e-3 : f.time >= 0.05 - 1e-12 ? 1e-3 : 0.0;
    add(f, 42, {0.02, 0.005 + lift}, 0.004);
    frames.push_back(f);
  }
  const FrostCycles c = frost_cycles(frames, {0.05, 0.10, 0.121}, 3); // two freezes, the end
  ASSERT_EQ(c.stones.size(), 1u);
  EXPECT_EQ(c.stones[0], 42u);
  EXPECT_EQ(c.fines.size(), 3u);
  ASSERT_EQ(c.time.size(), 3u);
  EXPECT_NEAR(c.time[0], 0.04, 1e-12); // the snapshot at 0.05 s already shows the heave
  EXPECT_NEAR(c.time[2], 0.12, 1e-12);
  EXPECT_NEAR(c.stone_height[2][0] - c.stone_height[0][0], 2e-3, 1e-12);
  EXPECT_NEAR(c.rise_per_cycle[0], 1e-3, 1e-12);
  EXPECT_NEAR(c.start_depth[0], -0.007, 1e-12); // sticks out 7 mm above the fines (top 2 mm)
  EXPECT_GT(c.surface_cover[0], 0.0);
  EXPECT_GT(c.sorting_index[0], 0.0);
}

TEST(PictureRequest, ParsesColourAndLayersAndNamesTheAllowedValues) {
  const PictureRequest r = parse_picture_request("force+chains+tracks");
  EXPECT_EQ(r.colour, "force");
  EXPECT_TRUE(r.chains);
  EXPECT_TRUE(r.tracks);
  EXPECT_EQ(picture_stem(r), "force_chains_tracks");
  EXPECT_EQ(picture_stem(parse_picture_request("size")), "size");
  EXPECT_NE(picture_request_problem("speed+chain").find("chains, tracks"), std::string::npos);
  EXPECT_NE(picture_request_problem("velocity").find("speed, size"), std::string::npos);
  EXPECT_TRUE(picture_request_problem("kind+tracks").empty());
}

} // namespace
} // namespace talus
