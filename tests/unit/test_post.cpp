// The analyses of snapshots (src/post) on frames built by hand, where the answer is known exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "talus/error.hpp"

#include "post/flow_profiles.hpp"
#include "post/frost_cycles.hpp"
#include "post/segregation.hpp"
#include "scenario/picture_request.hpp"

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

TEST(Discharge, ConstantFlowGivesOneRateInBothHalves) {
  // 5 grains per second pass y = 0 from t = 1 s to t = 9 s, 40 in all
  std::vector<Frame> frames;
  for (int k = 0; k <= 10; ++k) {
    Frame f;
    f.time = k;
    const int below = std::clamp(5 * (k - 1), 0, 40);
    for (int i = 0; i < 40; ++i)
      add(f, static_cast<std::uint32_t>(i), {0.0, i < below ? -0.1 : 0.1}, 0.01);
    frames.push_back(f);
  }
  const Discharge d = discharge(frames, 0.0);
  EXPECT_EQ(d.below.front(), 0u);
  EXPECT_EQ(d.below.back(), 40u);
  EXPECT_NEAR(d.rate, 5.0, 1e-12);
  EXPECT_NEAR(d.rate_first_half, 5.0, 1e-12);
  EXPECT_NEAR(d.rate_second_half, 5.0, 1e-12);
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
