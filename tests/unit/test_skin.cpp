// The automatic skin (simulation.skin = 0): its rule, its bounds, and that a simulation uses it
// at every build while its configuration (saved in checkpoints) keeps asking for it.
#include <gtest/gtest.h>

#include <cmath>

#include "neighbours/skin.hpp"
#include "simulation/simulation.hpp"

namespace talus {
namespace {

constexpr double radius = 1e-3, skin_dt = 1e-5;

TEST(AutomaticSkin, GrowsAsTheSquareRootOfTheSpeedBetweenATenthAndOneRadius) {
  const Domain open;
  EXPECT_DOUBLE_EQ(automatic_skin(0.0, skin_dt, radius, radius, open), 0.1 * radius); // at rest
  // sqrt(256 v skin_dt R) = 0.4 R at v = 0.0625 m/s; four times faster, twice the skin
  EXPECT_NEAR(automatic_skin(0.0625, skin_dt, radius, radius, open), 0.4 * radius, 1e-12);
  EXPECT_NEAR(automatic_skin(0.25, skin_dt, radius, radius, open), 0.8 * radius, 1e-12);
  EXPECT_DOUBLE_EQ(automatic_skin(100.0, skin_dt, radius, radius, open), radius); // capped
}

TEST(AutomaticSkin, LeavesAPeriodicBoxItsThreeInteractionRanges) {
  // a period of 3 x (2 R_max + 0.5 R): room for a skin of 0.5 R, less 1%
  const double period = 3.0 * (2.0 * radius + 0.5 * radius);
  const Domain box{{0.0, 0.0}, {period, 1.0}, true, false};
  EXPECT_NEAR(automatic_skin(100.0, skin_dt, radius, radius, box), 0.99 * 0.5 * radius, 1e-15);
  EXPECT_NEAR(automatic_skin(0.0625, skin_dt, radius, radius, box), 0.4 * radius, 1e-12); // room
}

// Two grains far apart, one moving: the list is built with the skin the rule gives for
// 0.0625 m/s, and the configuration still says "automatic".
TEST(AutomaticSkin, ASimulationBuildsItsListsWithIt) {
  World w;
  Material m;
  m.normal_stiffness = 1.0e4;
  w.materials = {m};
  w.add_particle({.position = {0.0, 0.0}, .radius = radius, .velocity = {0.0625, 0.0}});
  w.add_particle({.position = {0.5, 0.0}, .radius = radius});
  SimulationConfig c;
  c.timestep = skin_dt;
  Simulation s(std::move(w), c);
  EXPECT_NEAR(s.neighbours().skin, 0.4 * radius, 1e-12);
  EXPECT_EQ(s.config().skin, 0.0);
  // it moves half the skin (0.2 mm) in 320 steps: rebuilt, with the same rule
  const auto builds = s.neighbours().builds;
  s.run(400);
  EXPECT_EQ(s.neighbours().builds, builds + 1);
  EXPECT_NEAR(s.neighbours().skin, 0.4 * radius, 1e-12);
}

// A grain at rest beside a wall that moves: the wall's ends set off rebuilds, so its speed
// chooses the skin (0.0625 m/s: 0.4 R, as for a grain that fast).
TEST(AutomaticSkin, FollowsAMovingWall) {
  Particles p;
  p.add({.position = {0.0, 0.0}, .radius = radius, .mass = 1.0, .inertia = 1.0});
  Segments walls(1);
  walls[0].a = {-0.1, -0.01};
  walls[0].b = {0.1, -0.01};
  EXPECT_DOUBLE_EQ(automatic_skin(p, walls, Domain{}, skin_dt), 0.1 * radius); // all at rest
  walls[0].velocity = {0.0625, 0.0};
  EXPECT_NEAR(automatic_skin(p, walls, Domain{}, skin_dt), 0.4 * radius, 1e-12);
  walls[0].velocity = {};
  walls[0].angular_velocity = 0.625; // about its pivot at the origin: 0.0625 m/s at the ends
  EXPECT_NEAR(automatic_skin(p, walls, Domain{}, skin_dt),
              0.4 * radius * std::sqrt(std::sqrt(1.01)), 1e-12);
}

} // namespace
} // namespace talus
