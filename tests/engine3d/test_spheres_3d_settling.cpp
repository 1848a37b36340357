// Spheres poured into a box settle: their energy only falls, the bed comes to rest and the floor
// and the walls carry its weight. And what the 3D engine does not have yet is refused, not run
// wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "engine3d/simulation3.hpp"
#include "support/two_body.hpp"
#include "talus/error.hpp"

namespace talus {
namespace {

constexpr double g_settle = 9.81;

// n spheres of radius 2 mm +- 10% on a loose lattice above the floor of a 24 mm box.
Scene3 poured(std::size_t n) {
  Material m = testing::elastic_material();
  m.restitution = 0.5;
  m.friction = 0.5;
  Scene3 scene;
  scene.materials = {m};
  scene.gravity = {0.0, 0.0, -g_settle};
  const double r = 2e-3, side = 24e-3;
  scene.plates = box_planes({0.0, 0.0, 0.0}, {side, side, 10.0 * side}, 0, true);
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto at = [&](std::size_t c) { return r * (1.5 + 2.5 * static_cast<double>(c)); };
  for (std::size_t k = 0; k < n; ++k)
    scene.add_sphere(
        {.position = {at(k % 4) + 0.2 * r * u(rng), at((k / 4) % 4) + 0.2 * r * u(rng), at(k / 16)},
         .radius = r * (1.0 + 0.1 * u(rng))});
  return scene;
}

Settings3 settings_for(const Scene3& scene) {
  const double mass = scene.spheres.mass[0];
  return {.timestep = linear_collision_time(scene.materials[0].normal_stiffness, 0.0, mass) / 30.0};
}

// The energy (kinetic, rotational, gravity's and the contacts' elastic) of a bed of damped
// frictional spheres falls; velocity Verlet lets it swing by O(dt^2) of a contact's energy while a
// contact loads and unloads, so a rise is allowed up to a thousandth of the energy the fall
// releases. At rest, the walls carry the weight.
TEST(Settling3, ABedPouredIntoABoxComesToRestOnItsFloor) {
  const Scene3 scene = poured(96);
  Simulation3 s(scene, settings_for(scene));
  double weight = 0.0;
  for (std::size_t i = 0; i < scene.spheres.size(); ++i) weight += scene.spheres.mass[i] * g_settle;
  const double e0 = s.energies().total();
  double lowest = e0, worst_rise = 0.0;
  for (int k = 0; k < 400; ++k) {
    s.run(250);
    const double e = s.energies().total();
    worst_rise = std::max(worst_rise, e - lowest);
    lowest = std::min(lowest, e);
  }
  const Energies3 end = s.energies();
  const double released = e0 - end.total();
  ASSERT_GT(released, 0.0);
  EXPECT_LT(worst_rise, 1e-3 * released);
  EXPECT_LT(end.kinetic + end.rotational, 1e-6 * released);
  Vec3 on_plates{}; // the floor and, through friction, the sides (Janssen)
  for (const Plane& p : s.scene().plates) on_plates += p.force;
  // what is left is the bed's last ringing: the walls carry the weight to 1e-4 of it, and
  // their forces balance sideways as closely
  EXPECT_NEAR(-on_plates.z, weight, 1e-4 * weight);
  EXPECT_LT(std::abs(on_plates.x) + std::abs(on_plates.y), 1e-4 * weight);
  EXPECT_GT(s.contact_count(), scene.spheres.size()); // a bed, not a layer of loose grains
  // frictional spheres at rest: between the isostatic 4 (mu large) and 6 (mu 0) in the bulk,
  // fewer at the free top and along the walls
  EXPECT_GT(s.coordination(), 3.0);
  EXPECT_LT(s.coordination(), 6.5);
}

// Each sphere sums its contacts' forces in a fixed order whatever the threads: a run of 1200
// spheres falling and colliding is the same to the bit on one thread and on two, with velocity
// Verlet and with Gear.
TEST(Threads3, ARunIsBitIdenticalOnOneAndTwoThreads) {
  const Scene3 scene = poured(1200);
  for (const Integrator integrator : {Integrator::verlet, Integrator::gear}) {
    SCOPED_TRACE(std::string(to_string(integrator)));
    Settings3 one = settings_for(scene);
    one.integrator = integrator;
    Settings3 two = one;
    one.threads = 1;
    two.threads = 2;
    Simulation3 a(scene, one), b(scene, two);
    ASSERT_EQ(b.threads(), 2);
    std::size_t touching = 0;
    for (int k = 0; k < 40; ++k) {
      a.run(100);
      b.run(100);
      touching += a.contact_count();
    }
    EXPECT_GT(touching, 100u);
    const Spheres &p = a.scene().spheres, &q = b.scene().spheres;
    const auto same = [](const std::vector<Vec3>& u, const std::vector<Vec3>& v) {
      return std::memcmp(u.data(), v.data(), u.size() * sizeof(Vec3)) == 0;
    };
    EXPECT_TRUE(same(p.position, q.position));
    EXPECT_TRUE(same(p.velocity, q.velocity));
    EXPECT_TRUE(same(p.angular_velocity, q.angular_velocity));
    EXPECT_EQ(a.list().builds, b.list().builds);
  }
}

TEST(Refusals3, ASphereMovedByADriverIsNotThereYet) {
  Scene3 scene;
  EXPECT_THROW(scene.add_sphere({.position = {}, .radius = 1e-3, .kind = Kind::moved}),
               InvalidArgument);
  EXPECT_THROW(scene.add_sphere({.position = {}, .radius = 1e-3, .material = 3}), InvalidArgument);
}

TEST(Guard3, ATimestepTooLongStopsWithTheOverlapThatShowsIt) {
  const Scene3 scene = poured(32);
  Settings3 settings = settings_for(scene);
  settings.timestep *= 40.0;
  try {
    Simulation3 s(scene, settings);
    s.run(20000);
    FAIL() << "an unstable run went on";
  } catch (const InstabilityError& e) {
    EXPECT_NE(std::string(e.what()).find("overlaps"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace talus
