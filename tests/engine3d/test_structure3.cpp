// The structure of a 3D packing (analysis/structure3.hpp) against closed forms:
// - the volume of a sphere in a box: whole, none, a cap cut by one side (pi h^2 (3r - h) / 3),
//   the centre on an edge (a quarter) or a corner (an eighth), and boxes cutting a sphere at
//   random against a Monte Carlo count;
// - the packing fraction of a simple cubic lattice, pi/6, in a periodic box whose sides cut
//   through spheres (their images fill the cuts);
// - the load-bearing network: a lattice on a floor keeps every sphere with its contacts counted,
//   a sphere with too few is a rattler, and taking out rattlers goes on down an open chain;
// - the contacts a sphere needs: 4 without friction, 3 with it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "analysis/structure3.hpp"
#include "support/two_body.hpp"
#include "talus/law_table.hpp"

namespace talus {
namespace {

using testing::elastic_material;

constexpr double pi = std::numbers::pi;

double ball(double r) {
  return 4.0 / 3.0 * pi * r * r * r;
}

// The Gauss-Legendre sums between the heights where the slices' area turns a kink are exact for
// a slice area polynomial in z (the sphere whole, or cut by the box's floor or lid, an edge or a
// corner through its centre). A side that cuts the slices makes the area rise as a power 3/2 of
// the height where a slice first reaches it; the smoothing map leaves a few 1e-12 of the sphere
// there: 1e-11.
constexpr double polynomial = 1e-13, cut = 1e-11;

TEST(Structure3, ASphereInABoxHasTheVolumeOfWhatTheBoxHolds) {
  const double r = 0.3;
  const Vec3 c{0.0, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(sphere_box_volume(c, r, {-1, -1, -1}, {1, 1, 1}), ball(r));
  EXPECT_EQ(sphere_box_volume(c, r, {0.3, -1, -1}, {1, 1, 1}), 0.0);
  // a cap of height h beyond a side, along each axis
  for (const double h : {0.05, 0.3, 0.45}) {
    const double cap = pi * h * h * (3 * r - h) / 3.0;
    EXPECT_NEAR(sphere_box_volume(c, r, {-1, -1, -1}, {r - h, 1, 1}), ball(r) - cap, cut * ball(r));
    EXPECT_NEAR(sphere_box_volume(c, r, {-1, r - h, -1}, {1, 1, 1}), cap, cut * ball(r));
    EXPECT_NEAR(sphere_box_volume(c, r, {-1, -1, -1}, {1, 1, r - h}), ball(r) - cap,
                polynomial * ball(r));
  }
  EXPECT_NEAR(sphere_box_volume(c, r, {0, 0, -1}, {1, 1, 1}), ball(r) / 4, polynomial * ball(r));
  EXPECT_NEAR(sphere_box_volume(c, r, {0, -1, 0}, {1, 1, 1}), ball(r) / 4, polynomial * ball(r));
  EXPECT_NEAR(sphere_box_volume(c, r, {0, 0, 0}, {1, 1, 1}), ball(r) / 8, polynomial * ball(r));
}

TEST(Structure3, BoxesCuttingASphereAnyhowAgreeWithAMonteCarloCount) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double r = 1.0;
  constexpr int samples = 400000;
  for (int trial = 0; trial < 5; ++trial) {
    const Vec3 lo{unit(random) * 0.8, unit(random) * 0.8, unit(random) * 0.8};
    const Vec3 hi{lo.x + 0.3 + std::abs(unit(random)), lo.y + 0.3 + std::abs(unit(random)),
                  lo.z + 0.3 + std::abs(unit(random))};
    int in = 0;
    for (int k = 0; k < samples; ++k) {
      const Vec3 p{unit(random), unit(random), unit(random)};
      in += norm2(p) < 1.0 && p.x >= lo.x && p.x < hi.x && p.y >= lo.y && p.y < hi.y &&
            p.z >= lo.z && p.z < hi.z;
    }
    const double fraction = static_cast<double>(in) / samples;
    // the count's standard deviation, sqrt(f (1 - f) / n) of the cube's 8: five of them
    const double sigma = 8.0 * std::sqrt(fraction * (1 - fraction) / samples);
    EXPECT_NEAR(sphere_box_volume({0, 0, 0}, r, lo, hi), 8.0 * fraction, 5.0 * sigma)
        << "trial " << trial;
  }
}

// A simple cubic lattice of n^3 spheres of radius r, spacing 2r (less `squeeze` so neighbours
// overlap), starting at `first`, in a box periodic along every axis.
Simulation3 lattice(int n, double r, double squeeze, Vec3 first) {
  Material m = elastic_material();
  m.friction = 0.0;
  Scene3 scene;
  scene.materials = {m};
  const double a = 2.0 * r - squeeze;
  scene.domain = {.lo = {0, 0, 0}, .hi = {n * a, n * a, n * a}, .periodic = {true, true, true}};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        scene.add_sphere({.position = first + Vec3{i * a, j * a, k * a}, .radius = r});
  return Simulation3(std::move(scene),
                     {.timestep = 1e-6, .tangential_law = law_id<Frictionless>, .threads = 1});
}

TEST(Structure3, ACubicLatticeFillsPiOverSixOfAPeriodicBoxThatCutsIt) {
  const double r = 0.01;
  // spheres cut by every side of the box: their images fill it
  const Simulation3 sim = lattice(4, r, 0.0, {0.3 * r, 0.0, 0.55 * r});
  const Domain3& domain = sim.scene().domain;
  EXPECT_NEAR(packing_fraction(sim, domain.lo, domain.hi), pi / 6, cut);
  // an inner box of whole cells: again pi/6
  EXPECT_NEAR(packing_fraction(sim, {0.3 * r, 0.0, 0.55 * r}, {4.3 * r, 4 * r, 4.55 * r}), pi / 6,
              cut);
}

TEST(Structure3, ALatticeHoldsItsSpheresAndALooseOneRattles) {
  const double r = 0.01;
  const Simulation3 sim = lattice(4, r, 1e-5, {r, r, r});
  const Domain3& domain = sim.scene().domain;
  LoadBearing held = load_bearing(sim, domain.lo, domain.hi, 4);
  EXPECT_EQ(held.grains, 64u);
  EXPECT_EQ(held.rattlers, 0u);
  EXPECT_DOUBLE_EQ(held.coordination, 6.0);
  // six contacts each: with 7 needed, every one goes
  held = load_bearing(sim, domain.lo, domain.hi, 7);
  EXPECT_EQ(held.rattlers, 64u);
  EXPECT_EQ(held.coordination, 0.0);
}

TEST(Structure3, TakingOutRattlersGoesOnDownAnOpenChain) {
  // five spheres in a row, touching: with two contacts needed, the ends go, then their
  // neighbours, then the middle; closed into a ring through a periodic side, none goes
  for (const bool ring : {false, true}) {
    Material m = elastic_material();
    Scene3 scene;
    scene.materials = {m};
    const double r = 0.01, a = 2.0 * r - 1e-5;
    scene.domain = {.lo = {0, 0, 0}, .hi = {5 * a + (ring ? 0.0 : 4 * r), 0.1, 0.1}};
    scene.domain.periodic = {ring, false, false};
    for (int k = 0; k < 5; ++k)
      scene.add_sphere({.position = {r + k * a, 0.05, 0.05}, .radius = r});
    const Simulation3 sim(std::move(scene), {.timestep = 1e-6, .threads = 1});
    const LoadBearing held = load_bearing(sim, sim.scene().domain.lo, sim.scene().domain.hi, 2);
    EXPECT_EQ(held.grains, 5u);
    EXPECT_EQ(held.rattlers, ring ? 0u : 5u) << (ring ? "ring" : "chain");
    EXPECT_DOUBLE_EQ(held.coordination, ring ? 2.0 : 0.0);
  }
}

TEST(Structure3, ASphereNeedsFourContactsWithoutFrictionAndThreeWithIt) {
  const auto needed = [](TangentialLaw law, double friction) {
    Material m = elastic_material();
    m.friction = friction;
    Scene3 scene;
    scene.materials = {m};
    scene.add_sphere({.position = {0.5, 0.5, 0.5}, .radius = 0.01});
    return contacts_needed(
        Simulation3(std::move(scene), {.timestep = 1e-6, .tangential_law = law, .threads = 1}));
  };
  EXPECT_EQ(needed(law_id<Frictionless>, 0.5), 4);
  EXPECT_EQ(needed(law_id<CundallStrack>, 0.0), 4);
  EXPECT_EQ(needed(law_id<CundallStrack>, 0.5), 3);
}

} // namespace
} // namespace talus
