// talus bench chute's system (scenario3d/chute_bench.hpp): the counts, the frozen base, the laws
// and gravity of LAMMPS' in.chute, no overlap at the start, a layer that flows down the slope
// over its base without going unstable, and its tiling across the slope (the same state, every
// copy feeling what its original feels).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine3d/simulation3.hpp"
#include "scenario3d/chute_bench.hpp"
#include "talus/error.hpp"

namespace talus {
namespace {

TEST(ChuteBench, ThirtyTwoThousandSpheresStandOnAFortyByTwentyBase) {
  const ChuteBench c = build_chute_bench(32000);
  EXPECT_EQ(c.nx, 40u);
  EXPECT_EQ(c.ny, 20u);
  EXPECT_EQ(c.scene.spheres.size(), 32000u);
  const auto fixed =
      std::count(c.scene.spheres.kind.begin(), c.scene.spheres.kind.end(), Kind::fixed);
  EXPECT_EQ(fixed, 800);
  EXPECT_TRUE(c.scene.domain.periodic[0] && c.scene.domain.periodic[1]);
  EXPECT_FALSE(c.scene.domain.periodic[2]);
  EXPECT_THROW(build_chute_bench(999), InvalidArgument);
}

// in.chute: gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0, fix gravity 1.0 chute 26.0,
// timestep 0.0001, neighbor 0.1; the exact numbers of the input, so the comparisons are exact.
TEST(ChuteBench, HasTheLawsGravityAndStepOfLammpsChuteInput) {
  const ChuteBench c = build_chute_bench(1000);
  const Material& m = c.scene.materials.at(0);
  EXPECT_EQ(m.normal_stiffness, 2.0e5);
  EXPECT_EQ(m.tangential_stiffness_ratio, 2.0 / 7.0);
  EXPECT_EQ(m.normal_damping_rate, 50.0);
  EXPECT_EQ(m.tangential_damping, 0.0);
  EXPECT_EQ(m.friction, 0.5);
  EXPECT_EQ(m.density, 1.0);
  EXPECT_EQ(c.settings.normal_law, law_id<LinearSpringDashpot>);
  EXPECT_EQ(c.settings.tangential_law, law_id<CundallStrack>);
  EXPECT_EQ(c.settings.timestep, 1.0e-4);
  EXPECT_EQ(c.settings.skin, 0.1);
  // a unit vector 26 degrees from -z towards +x (rounding of sin and cos: 1e-15)
  EXPECT_NEAR(norm(c.scene.gravity), 1.0, 1e-15);
  EXPECT_NEAR(std::atan2(c.scene.gravity.x, -c.scene.gravity.z), 26.0 * std::numbers::pi / 180.0,
              1e-15);
  EXPECT_EQ(c.scene.gravity.y, 0.0);
}

TEST(ChuteBench, NoSphereOverlapsAnotherAtTheStart) {
  const ChuteBench c = build_chute_bench(1000);
  const Spheres& s = c.scene.spheres;
  const Vec3 l = c.scene.domain.size();
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      Vec3 d = s.position[i] - s.position[j];
      d.x -= l.x * std::round(d.x / l.x); // the nearest periodic image
      d.y -= l.y * std::round(d.y / l.y);
      ASSERT_GE(norm(d), s.radius[i] + s.radius[j]) << "spheres " << i << " and " << j;
    }
}

// After the layer has landed on its base it moves down the slope (+x), not across it, and the
// frozen base has not moved.
TEST(ChuteBench, TheLayerFlowsDownTheSlopeOverItsFrozenBase) {
  ChuteBench c = build_chute_bench(1000);
  c.settings.threads = 1;
  const std::vector<Vec3> start = c.scene.spheres.position;
  Simulation3 sim(c.scene, c.settings);
  sim.run(20000);
  const Spheres& s = sim.scene().spheres;
  Vec3 mean{};
  std::size_t free = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s.is_free(i)) {
      const Vec3& was = start[s.id[i]]; // by id: the spheres are renumbered as they flow
      EXPECT_TRUE(s.position[i].x == was.x && s.position[i].y == was.y && s.position[i].z == was.z);
      continue;
    }
    mean += s.velocity[i];
    ++free;
  }
  mean = (1.0 / static_cast<double>(free)) * mean;
  EXPECT_GT(mean.x, 0.1);                    // down the slope, at 2 time units of flow
  EXPECT_LT(std::abs(mean.y), 0.1 * mean.x); // hardly across it
  EXPECT_GT(sim.contact_count(), 0u);
}

// A flowing layer tiled 2 x 2: four copies of every sphere, each with its original's velocity and
// spin, and, with the springs both start without, its original's contact force: the copies
// see the same neighbours through the larger box's sides as the originals through the smaller
// one's. To 1e-8 N (the largest forces are about 1e2 N): a position shifted by whole box lengths
// rounds at the larger coordinate's scale (an ulp of 80 is 1.4e-14), which k_n = 2e5 and the
// neighbours' own rounding turn into forces different by some 1e-9 N.
TEST(ChuteBench, ATiledLayerIsFourCopiesFeelingWhatTheOriginalsFeel) {
  ChuteBench c = build_chute_bench(1000);
  c.settings.threads = 1;
  c.settings.sort_interval = 0;
  Simulation3 flowed(c.scene, c.settings);
  flowed.run(12000);
  const Scene3 tiled = tiled_across(flowed.scene(), 2);
  const Simulation3 one(flowed.scene(), c.settings), four(tiled, c.settings);
  const Spheres &a = one.scene().spheres, &b = four.scene().spheres;
  ASSERT_EQ(b.size(), 4 * a.size());
  EXPECT_EQ(four.scene().domain.size().x, 2.0 * one.scene().domain.size().x);
  EXPECT_EQ(four.scene().domain.size().y, 2.0 * one.scene().domain.size().y);
  ASSERT_GT(one.contact_count(), 10u); // the lowest layer has landed on the base
  EXPECT_EQ(four.contact_count(), 4 * one.contact_count());
  for (std::size_t copy = 0; copy < 4; ++copy)
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::size_t k = copy * a.size() + i;
      ASSERT_EQ(b.velocity[k].x, a.velocity[i].x);
      ASSERT_EQ(b.angular_velocity[k].z, a.angular_velocity[i].z);
      ASSERT_LT(norm(b.force[k] - a.force[i]), 1e-8) << "copy " << copy << ", sphere " << i;
    }
  Scene3 walled = flowed.scene();
  walled.domain.periodic[1] = false;
  EXPECT_THROW(tiled_across(walled, 2), InvalidArgument);
}

} // namespace
} // namespace talus
