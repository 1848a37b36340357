// The load-bearing network (analysis/rattlers.hpp) on clusters whose rattlers are known, and the
// jamming fits (post/jamming.hpp) on steps laid out along their closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/rattlers.hpp"
#include "post/jamming.hpp"
#include "simulation/simulation.hpp"

namespace talus {
namespace {

constexpr double jam_r = 0.01;
constexpr double jam_touching = 2.0 * jam_r * 0.999; // centres a little closer than 2r: a contact

// Frictionless disks at rest at the given centres, no gravity, no walls.
Simulation disks(const std::vector<Vec2>& centres) {
  World w;
  Material m;
  m.friction = 0.0;
  w.materials = {m};
  w.gravity = {0.0, 0.0};
  for (const Vec2 c : centres)
    w.add_particle({.position = c, .radius = jam_r, .shape = Shape::disk});
  SimulationConfig c;
  c.timestep = 1e-6;
  c.tangential_law = law_id<Frictionless>;
  return Simulation(std::move(w), c);
}

// A hexagon of six disks around a seventh, each touching the centre and its two neighbours:
// every disk has at least 3 contacts, none is a rattler, and Z = 2 x 12 contacts / 7 disks.
// A disk touching one outer disk is a rattler; so is a pair hanging from the cluster by one
// contact (the outer one of the pair first, then the inner, which is left with one), and the
// outer disks they touched keep their 3. A disk in the groove of two outer disks needs friction
// to be held (2 contacts).
TEST(LoadBearing, TakesOutRattlersOneAfterTheOther) {
  std::vector<Vec2> c{{0.0, 0.0}};
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3.0;
    c.push_back({jam_touching * std::cos(a), jam_touching * std::sin(a)});
  }
  const Simulation cluster = disks(c);
  const LoadBearing all = load_bearing(cluster, {-1.0, -1.0}, {1.0, 1.0}, 3);
  EXPECT_EQ(all.grains, 7u);
  EXPECT_EQ(all.rattlers, 0u);
  EXPECT_NEAR(all.coordination, 24.0 / 7.0, 1e-12);

  c.push_back(c[1] + Vec2{jam_touching, 0.0});        // on disk 1 alone
  c.push_back(c[4] + Vec2{-jam_touching, 0.0});       // a pair: hangs on disk 4
  c.push_back(c[4] + Vec2{-2.0 * jam_touching, 0.0}); // its outer disk
  const Simulation hung = disks(c);
  const LoadBearing net = load_bearing(hung, {-1.0, -1.0}, {1.0, 1.0}, 3);
  EXPECT_EQ(net.grains, 10u);
  EXPECT_EQ(net.rattlers, 3u);
  EXPECT_TRUE(net.rattler[7] && net.rattler[8] && net.rattler[9]);
  EXPECT_NEAR(net.coordination, 24.0 / 7.0, 1e-12);
  // a disk in the groove between two outer disks: a rattler without friction, held with it
  c.push_back(c[1] + c[2]);
  const Simulation groove = disks(c);
  EXPECT_TRUE(load_bearing(groove, {-1.0, -1.0}, {1.0, 1.0}, 3).rattler[10]);
  const LoadBearing frictional = load_bearing(groove, {-1.0, -1.0}, {1.0, 1.0}, 2);
  EXPECT_FALSE(frictional.rattler[10]);
  EXPECT_EQ(frictional.rattlers, 2u); // the pair; the disk on disk 1 touches the groove's too
  // the region counts the grains with their centres in it
  EXPECT_EQ(load_bearing(hung, {-0.5 * jam_r, -0.5 * jam_r}, {0.5 * jam_r, 0.5 * jam_r}, 3).grains,
            1u);
}

// A fixed grain counts as a wall for the grains it touches, whatever its index: with it first
// in the list it is the first particle of its pairs (this once read a wall as grain 2^32 - 1).
// The hexagon's centre fixed: each outer disk keeps its 3 contacts, one of them the wall.
TEST(LoadBearing, AFixedGrainIsAWallToTheGrainsItHolds) {
  World w;
  Material m;
  m.friction = 0.0;
  w.materials = {m};
  w.gravity = {0.0, 0.0};
  w.add_particle(
      {.position = {0.0, 0.0}, .radius = jam_r, .kind = Kind::fixed, .shape = Shape::disk});
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3.0;
    w.add_particle({.position = {jam_touching * std::cos(a), jam_touching * std::sin(a)},
                    .radius = jam_r,
                    .shape = Shape::disk});
  }
  SimulationConfig c;
  c.timestep = 1e-6;
  c.tangential_law = law_id<Frictionless>;
  const Simulation ring(std::move(w), c);
  const LoadBearing net = load_bearing(ring, {-1.0, -1.0}, {1.0, 1.0}, 3);
  EXPECT_EQ(net.grains, 6u);
  EXPECT_EQ(net.rattlers, 0u);
  EXPECT_NEAR(net.coordination, 3.0, 1e-12);
}

// Steps on phi = phi_J + p / B and Z = Z_J + A sqrt(phi - phi_J) give back the four numbers to
// rounding (1e-9: the least squares of exact data).
TEST(JammingFit, GivesBackTheClosedForms) {
  const double phi_j = 0.842, bulk = 5.0e4, z_j = 4.0, a = 3.5;
  std::vector<JammingStep> steps;
  for (const double p : {1000.0, 300.0, 100.0, 30.0, 10.0, 3.0}) {
    JammingStep s;
    s.pressure = p;
    s.packing = phi_j + p / bulk;
    s.coordination = z_j + a * std::sqrt(p / bulk);
    steps.push_back(s);
  }
  const JammingFit f = fit_jamming(steps);
  ASSERT_TRUE(f.measured) << f.why_not;
  EXPECT_NEAR(f.phi_j, phi_j, 1e-9);
  EXPECT_NEAR(f.bulk, bulk, 1e-9 * bulk);
  EXPECT_NEAR(f.z_j, z_j, 1e-9);
  EXPECT_NEAR(f.z_slope, a, 1e-9);
  steps.resize(2);
  EXPECT_FALSE(fit_jamming(steps).measured);
}

} // namespace
} // namespace talus
