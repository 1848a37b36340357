// The stress of spheres in 3D (analysis/stress3.hpp) against closed forms:
// - a column of spheres at rest on a floor: static equilibrium makes the contact stress's
//   integral over the box V sigma_zz = g sum m_i z_i (the virial of the weights; the floor's
//   contact points lie at z = 0, so its forces add no moment), every other component 0, the
//   major direction z and the fabric all z z;
// - spheres apart: the kinetic part is (1/V) sum m u u about their mean velocity, the contact
//   part 0;
// - each sphere of that column: -sum f l over its contacts is m g (k r_above + (k + 1) r_below),
//   k the spheres above it, r_above and r_below its branches (its radius less half the overlap
//   with its neighbour, or the whole overlap with the floor), and its stresses times the spheres'
//   volumes sum to the box's contact part times the box's;
// - the principal values of a tensor and its directions, the major first.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "analysis/stress3.hpp"
#include "support/two_body.hpp"
#include "talus/closed_forms.hpp"
#include "talus/law_table.hpp"

namespace talus {
namespace {

using testing::elastic_material;

constexpr double radius = 1e-3, g_earth = 9.81;

// Ten spheres stacked on a floor, frictionless, let come to rest.
Simulation3 resting_column(int spheres) {
  Material m = elastic_material();
  m.restitution = 0.3;
  m.friction = 0.0;
  Scene3 scene;
  scene.materials = {m};
  scene.gravity = {0.0, 0.0, -g_earth};
  scene.domain = {.lo = {-0.01, -0.01, 0.0}, .hi = {0.01, 0.01, 0.05}};
  scene.plates.push_back(make_plane({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}));
  for (int k = 0; k < spheres; ++k)
    scene.add_sphere({.position = {0.0, 0.0, radius + 2.0 * radius * k}, .radius = radius});
  const double mass = scene.spheres.mass[0];
  Simulation3 sim(std::move(scene),
                  {.timestep = linear_collision_time(m.normal_stiffness, 0.0, mass) / 40.0,
                   .tangential_law = law_id<Frictionless>,
                   .threads = 1});
  sim.run(40000);
  return sim;
}

TEST(Stress3, AColumnAtRestCarriesTheVirialOfItsWeights) {
  const Simulation3 sim = resting_column(10);
  const Spheres& s = sim.scene().spheres;
  double kinetic = 0.0, virial = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    kinetic += 0.5 * s.mass[i] * norm2(s.velocity[i]);
    virial += s.mass[i] * g_earth * s.position[i].z;
  }
  const Domain3& domain = sim.scene().domain;
  const RegionStress3 r = region_stress(sim, domain.lo, domain.hi);
  // at rest: what motion is left is a speck of the weight's work over an overlap
  ASSERT_LT(kinetic, 1e-15 * virial) << "the column has not come to rest";
  EXPECT_EQ(r.spheres, 10u);
  EXPECT_EQ(r.contacts, 9u);
  // the contact forces are the laws' at the state, whose rest leaves the weights balanced to
  // rounding: 1e-9 of the whole
  EXPECT_NEAR(r.contact(2, 2) * r.volume, virial, 1e-9 * virial);
  const double scale = r.contact(2, 2);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      if (a != 2 || b != 2) {
        EXPECT_NEAR(r.contact(a, b), 0.0, 1e-12 * scale) << a << b;
      }
  EXPECT_NEAR(r.fabric(2, 2), 1.0, 1e-12);
  const Principal3 p = principal(r.total());
  EXPECT_NEAR(p.values(0), scale, 1e-9 * scale);
  EXPECT_NEAR(std::abs(p.directions(2, 0)), 1.0, 1e-12);
  // and the thermo columns say so: stress_zz the ninth, the major direction's z the 22nd
  const std::string row = stress_thermo_columns(r);
  EXPECT_EQ(std::ranges::count(row, ','), std::ranges::count(stress_thermo_header(), ','));
}

TEST(Stress3, EachSphereOfAColumnAtRestCarriesTheWeightAboveIt) {
  constexpr int count = 10;
  const Simulation3 sim = resting_column(count);
  const Spheres& s = sim.scene().spheres;
  const std::vector<Tensor3> stress = sphere_stresses(sim);
  ASSERT_EQ(stress.size(), s.size());
  std::vector<std::size_t> by_height(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) by_height[i] = i;
  std::ranges::sort(by_height, [&](auto a, auto b) { return s.position[a].z > s.position[b].z; });
  const double volume = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  const Domain3& domain = sim.scene().domain;
  const RegionStress3 whole = region_stress(sim, domain.lo, domain.hi);
  Tensor3 sum = Tensor3::Zero();
  for (int k = 0; k < count; ++k) {
    const std::size_t i = by_height[static_cast<std::size_t>(k)];
    const double above = k == 0 ? 0.0 : 0.5 * (s.position[by_height[k - 1]].z - s.position[i].z);
    const double below =
        k == count - 1 ? s.position[i].z : 0.5 * (s.position[i].z - s.position[by_height[k + 1]].z);
    const double weight = s.mass[i] * g_earth;
    const double expected = weight * (k * above + (k + 1) * below) / volume;
    // the forces balance the weights to rounding at rest, as above: 1e-9
    EXPECT_NEAR(stress[i](2, 2), expected, 1e-9 * expected) << "sphere " << k << " from the top";
    EXPECT_NEAR(stress[i](0, 0), 0.0, 1e-12 * expected);
    sum += volume * stress[i];
  }
  // the same forces and branches: to rounding
  EXPECT_TRUE(sum.isApprox(whole.contact * whole.volume, 1e-12));
}

TEST(Stress3, SpheresApartCarryTheirMomentumFluxAboutTheMean) {
  Material m = elastic_material();
  Scene3 scene;
  scene.materials = {m};
  scene.domain = {.lo = {0.0, 0.0, 0.0}, .hi = {0.1, 0.1, 0.1}};
  const Vec3 u[3] = {{1.0, 0.0, 0.0}, {0.0, -2.0, 1.0}, {-1.0, 2.0, 0.5}};
  for (int k = 0; k < 3; ++k)
    scene.add_sphere(
        {.position = {0.02 + 0.03 * k, 0.05, 0.05}, .radius = radius, .velocity = u[k]});
  const Simulation3 sim(std::move(scene), {.timestep = 1e-6, .threads = 1});
  const Spheres& s = sim.scene().spheres;
  const RegionStress3 r = region_stress(sim, {0.0, 0.0, 0.0}, {0.1, 0.1, 0.1});
  Vec3 mean{};
  double mass = 0.0;
  for (int k = 0; k < 3; ++k) mean += s.mass[k] * u[k], mass += s.mass[k];
  mean = (1.0 / mass) * mean;
  Tensor3 expected = Tensor3::Zero();
  for (int k = 0; k < 3; ++k) {
    const Vec3 d = u[k] - mean;
    const Eigen::Vector3d v(d.x, d.y, d.z);
    expected += s.mass[k] * v * v.transpose() / 1e-3;
  }
  EXPECT_TRUE(r.contact.isZero(0.0));
  EXPECT_TRUE(r.kinetic.isApprox(expected, 1e-14));
  EXPECT_EQ(r.spheres, 3u);
  // a region holding one sphere: no spread about its own mean
  EXPECT_TRUE(region_stress(sim, {0.0, 0.0, 0.0}, {0.03, 0.1, 0.1}).kinetic.isZero(0.0));
}

TEST(Stress3, PrincipalValuesComeMajorFirstWithTheirDirections) {
  // diag(1, 3, 2) turned about z by 30 degrees
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  Tensor3 turn;
  turn << c, -s, 0, s, c, 0, 0, 0, 1;
  const Tensor3 t = turn * Eigen::Vector3d(1.0, 3.0, 2.0).asDiagonal() * turn.transpose();
  const Principal3 p = principal(t);
  EXPECT_NEAR(p.values(0), 3.0, 1e-14);
  EXPECT_NEAR(p.values(1), 2.0, 1e-14);
  EXPECT_NEAR(p.values(2), 1.0, 1e-14);
  // the major direction: the y axis turned, (-sin, cos, 0), up to its sign
  EXPECT_NEAR(std::abs(p.directions.col(0).dot(Eigen::Vector3d(-s, c, 0.0))), 1.0, 1e-14);
  EXPECT_NEAR(std::abs(p.directions(2, 1)), 1.0, 1e-14);
}

} // namespace
} // namespace talus
