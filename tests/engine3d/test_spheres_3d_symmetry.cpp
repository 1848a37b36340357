// The 3D engine's symmetries: a scene turned by a random rotation runs as the rotated scene
// (isotropy), a scene whose motion stays in a plane runs as the 2D engine's spheres in that
// plane, and momentum is conserved where nothing outside acts. None is to the bit: a rotation
// rounds each coordinate, and the 2D engine's lines (a scalar spring along t, the sums of two
// components, its SIMD lanes' order of additions) round otherwise than the 3D ones; the bounds
// below are a few hundred roundings of the quantities compared, and a wrong sign, lever or
// frame anywhere is off by the quantity itself.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "engine3d/simulation3.hpp"
#include "physics/single_impact.hpp"
#include "support/two_body.hpp"

namespace talus {
namespace {

struct Rotation {
  Eigen::Matrix3d q;
  Vec3 operator()(const Vec3& v) const {
    const Eigen::Vector3d r = q * Eigen::Vector3d(v.x, v.y, v.z);
    return {r.x(), r.y(), r.z()};
  }
};

Rotation random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  const Eigen::Vector3d axis = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
  return {Eigen::AngleAxisd(2.0 + 0.5 * g(rng), axis).toRotationMatrix()};
}

Scene3 rotated(const Scene3& scene, const Rotation& q) {
  Scene3 out = scene;
  Spheres& s = out.spheres;
  for (std::size_t i = 0; i < s.size(); ++i) {
    s.position[i] = q(s.position[i]);
    s.velocity[i] = q(s.velocity[i]);
    s.angular_velocity[i] = q(s.angular_velocity[i]);
  }
  for (Plane& p : out.plates) {
    p.centre = q(p.centre);
    p.normal = q(p.normal);
    p.axis_u = q(p.axis_u);
  }
  out.gravity = q(scene.gravity);
  return out;
}

// Spheres thrown about in a closed box under gravity, with friction and damping.
Scene3 spheres_in_a_box(std::mt19937& rng, std::size_t n, double spacing = 2.0) {
  Material m = testing::elastic_material();
  m.restitution = 0.7;
  m.friction = 0.4;
  Scene3 scene;
  scene.materials = {m};
  scene.gravity = {0.0, 0.0, -9.81};
  const double r = 1e-3, side = 12e-3;
  scene.plates = box_planes({0.0, 0.0, 0.0}, {side, side, side});
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t k = 0; k < n; ++k) {
    const auto at = [&](std::size_t c) { return r * (2.0 + spacing * static_cast<double>(c)); };
    const Vec3 site{at(k % 5), at((k / 5) % 5), at(k / 25)};
    scene.add_sphere({.position = site + 0.1 * r * Vec3{u(rng), u(rng), u(rng)},
                      .radius = r * (1.0 + 0.1 * u(rng)),
                      .velocity = 0.1 * Vec3{u(rng), u(rng), u(rng)},
                      .angular_velocity = 50.0 * Vec3{u(rng), u(rng), u(rng)}});
  }
  return scene;
}

// An overlap is a small difference of two positions: the rounding of the rotated positions is a
// larger part of it, and every collision after the first amplifies the difference (the motion of
// many grains is chaotic). Hence a short run from a packing whose grains overlap at the start,
// and a bound that is still a millionth of what a wrong sign or lever would give.
TEST(Isotropy3, ARotatedSceneRunsAsTheRotatedRun) {
  std::mt19937 rng(17);
  const Scene3 scene = spheres_in_a_box(rng, 40, 1.9);
  const Rotation q = random_rotation(rng);
  const double mass = scene.spheres.mass[0];
  const Settings3 settings{
      .timestep = linear_collision_time(scene.materials[0].normal_stiffness, 0.0, mass) / 50.0};
  Simulation3 a(scene, settings), b(rotated(scene, q), settings);
  std::size_t touching = 0; // contacts seen every 100 steps
  for (int k = 0; k < 5; ++k) {
    a.run(100);
    b.run(100);
    touching += a.contact_count();
  }
  ASSERT_GT(touching, 30u);
  double worst = 0.0, speed = 0.0;
  for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
    worst = std::max(worst, norm(q(a.scene().spheres.velocity[i]) - b.scene().spheres.velocity[i]));
    speed = std::max(speed, norm(a.scene().spheres.velocity[i]));
  }
  EXPECT_LT(worst, 1e-9 * speed) << "fastest " << speed << " m/s";
}

// The 2D engine's sphere hitting a floor obliquely with spin (single_impact.hpp, Hertz and
// Mindlin's spring, the regime of partial slip) against the 3D engine's, the floor turned at
// random and the spin about an axis out of the floor's plane.
TEST(Planar3, AnObliqueImpactInAPlaneIsThe2DEnginesSphere) {
  using namespace single_impact;
  Material m = testing::elastic_material();
  m.restitution = 0.9;
  m.friction = 0.3;
  Impact c{.grain = m,
           .radius = 1e-3,
           .velocity = {0.05, -0.1},
           .spin = -30.0,
           .integrator = Integrator::verlet};
  Simulation flat = impact(c);
  std::mt19937 rng(23);
  const Rotation q = random_rotation(rng);
  const auto lift = [&](Vec2 v) { return q(Vec3{v.x, v.y, 0.0}); };
  const Particles& p2 = flat.world().particles;
  Scene3 scene;
  scene.materials = flat.world().materials;
  scene.plates.push_back(make_plane({0.0, 0.0, 0.0}, lift({0.0, 1.0})));
  scene.plates.back().material = 1;
  scene.add_sphere({.position = lift(p2.position[0]),
                    .radius = c.radius,
                    .velocity = lift(p2.velocity[0]),
                    .angular_velocity = q(Vec3{0.0, 0.0, c.spin}),
                    .mass = p2.mass[0],
                    .inertia = p2.inertia[0]});
  Simulation3 s(std::move(scene), {.timestep = flat.config().timestep,
                                   .normal_law = c.normal,
                                   .tangential_law = c.tangential,
                                   .impact_speed = std::abs(c.velocity.y)});
  flat.run(600);
  s.run(600);
  ASSERT_GT(gap(flat), 0.0) << "still touching";
  const Spheres& p3 = s.scene().spheres;
  const double speed = norm(Vec2{c.velocity.x, c.velocity.y});
  EXPECT_GT(norm(p2.velocity[0] - Vec2{c.velocity.x, -c.velocity.y}), 0.05 * speed); // it hit
  EXPECT_LT(norm(p3.velocity[0] - lift(p2.velocity[0])), 1e-12 * speed);
  EXPECT_LT(norm(p3.angular_velocity[0] - q(Vec3{0.0, 0.0, p2.angular_velocity[0]})) * c.radius,
            1e-12 * speed);
  EXPECT_LT(norm(p3.position[0] - lift(p2.position[0])), 1e-12 * c.radius);
}

// Without gravity or plates, in a box periodic along every axis, the momentum of spheres that
// collide for many steps stays what it was (to the rounding of the force sums).
TEST(Momentum3, IsConservedInAPeriodicBox) {
  std::mt19937 rng(29);
  Scene3 scene = spheres_in_a_box(rng, 100);
  scene.plates.clear();
  scene.gravity = {};
  scene.domain = {
      .lo = {0.0, 0.0, 0.0}, .hi = {12e-3, 12e-3, 22e-3}, .periodic = {true, true, true}};
  const Settings3 settings{.timestep =
                               linear_collision_time(1e4, 0.0, scene.spheres.mass[0]) / 50.0};
  const auto momentum = [](const Spheres& s) {
    Vec3 total{};
    double scale = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      total += s.mass[i] * s.velocity[i];
      scale += s.mass[i] * norm(s.velocity[i]);
    }
    return std::pair{total, scale};
  };
  Simulation3 s(std::move(scene), settings);
  const auto [before, scale] = momentum(s.scene().spheres);
  std::size_t touching = 0;
  for (int k = 0; k < 20; ++k) {
    s.run(100);
    touching += s.contact_count();
  }
  EXPECT_GT(touching, 20u);
  EXPECT_LT(norm(momentum(s.scene().spheres).first - before), 1e-13 * scale);
}

// Without gravity or plates, in open space, the angular momentum about the origin of spheres that
// collide with friction (their spins taking up part of it) stays what it was. Velocity Verlet
// keeps it exactly, but each step rounds every position by up to half an ulp, which moves
// m r x v by as much, often the same way step after step in free flight: the bound is a millionth
// of what the contacts moved between the orbits and the spins, which a wrong torque or lever
// would leave unbalanced.
TEST(Momentum3, AngularMomentumIsConservedInOpenSpace) {
  std::mt19937 rng(31);
  Scene3 scene = spheres_in_a_box(rng, 60, 1.9);
  scene.plates.clear();
  scene.gravity = {};
  Vec3 centre{}; // the spheres thrown together, to collide again and again
  for (const Vec3& p : scene.spheres.position) centre += (1.0 / 60.0) * p;
  for (std::size_t i = 0; i < 60; ++i)
    scene.spheres.velocity[i] += -100.0 * (scene.spheres.position[i] - centre);
  const Settings3 settings{.timestep =
                               linear_collision_time(1e4, 0.0, scene.spheres.mass[0]) / 50.0};
  const auto angular_momentum = [](const Spheres& s) {
    Vec3 total{}, spins{};
    double scale = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      total +=
          s.mass[i] * cross(s.position[i], s.velocity[i]) + s.inertia[i] * s.angular_velocity[i];
      spins += s.inertia[i] * s.angular_velocity[i];
      scale += s.mass[i] * norm(s.position[i]) * norm(s.velocity[i]);
    }
    return std::tuple{total, spins, scale};
  };
  Simulation3 s(std::move(scene), settings);
  const auto [before, spins_before, scale] = angular_momentum(s.scene().spheres);
  std::size_t touching = 0;
  for (int k = 0; k < 10000; ++k) {
    s.step();
    touching += s.contact_count();
  }
  EXPECT_GT(touching, 2000u); // contacts times steps
  const auto [after, spins_after, unused] = angular_momentum(s.scene().spheres);
  const double exchanged = norm(spins_after - spins_before);
  EXPECT_GT(exchanged, 1e-3 * scale); // the contacts turned the spins
  EXPECT_LT(norm(after - before), 1e-6 * exchanged);
}

} // namespace
} // namespace talus
