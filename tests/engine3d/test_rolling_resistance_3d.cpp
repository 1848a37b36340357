// Rolling resistance in the native 3D engine (src/talus/rolling_resistance.hpp on vectors): a
// sphere rolling in any direction on a plate slows as the torque balance says and stops, rests on
// a slope below its angle and rolls down it above, as the closed forms of reference_values.hpp
// say (the 2D test's, for a sphere's inertia); between two spheres the torques are opposite.
#include <gtest/gtest.h>

#include <cmath>

#include "engine3d/simulation3.hpp"
#include "materials/timestep.hpp"
#include "physics/reference_values.hpp"
#include "support/two_body.hpp"

namespace talus {
namespace {

namespace ref = reference;

const double rolling_radius = 5.0e-3, rolling_g = 9.81, rolling_mu_r = 0.1;
const double rolling_heading =
    0.7; // rad: the direction of rolling in the floor's plane, off any axis
const Vec3 rolling_along{std::cos(rolling_heading), std::sin(rolling_heading), 0.0};
const Vec3 up{0.0, 0.0, 1.0};

// A sphere rolling without slip at `speed` along `along` on a floor (z = 0), gravity tilted by
// `slope` towards `along`; Cundall-Strack friction far above what rolling asks.
Simulation3 roll_on_floor(double speed, double slope) {
  Material m = testing::elastic_material(1.0e6);
  m.restitution = 0.3;
  m.friction = 0.8;
  m.rolling_friction = rolling_mu_r;
  Scene3 scene;
  scene.materials = {m};
  scene.gravity = rolling_g * std::sin(slope) * rolling_along - rolling_g * std::cos(slope) * up;
  scene.plates.push_back(make_plane({0.0, 0.0, 0.0}, up));
  const double mass = shape_mass(Shape::sphere, rolling_radius, m.density);
  const double sag = mass * rolling_g * std::cos(slope) / m.normal_stiffness;
  scene.add_sphere({.position = {0.0, 0.0, rolling_radius - sag},
                    .radius = rolling_radius,
                    .velocity = speed * rolling_along,
                    .angular_velocity = (speed / rolling_radius) * cross(up, rolling_along)});
  return Simulation3(std::move(scene),
                     {.timestep = linear_collision_time(m.normal_stiffness, 0.0, mass) / 50.0,
                      .tangential_law = law_id<CundallStrack>});
}

void run_until(Simulation3& s, double t) {
  while (s.time() < t) s.step();
}

TEST(RollingResistance3, ASphereRollingOnAPlateSlowsAsTheTorqueBalanceSays) {
  const double speed = 0.2;
  Simulation3 s = roll_on_floor(speed, 0.0);
  const double a = rolling_mu_r * rolling_g / (1.0 + ref::sphere_inertia_factor);
  const double t_stop = speed / a;
  const Spheres& p = s.scene().spheres;
  run_until(s, 0.25 * t_stop);
  const double t1 = s.time(), v1 = dot(p.velocity[0], rolling_along);
  run_until(s, 0.75 * t_stop);
  const double measured = (v1 - dot(p.velocity[0], rolling_along)) / (s.time() - t1);
  EXPECT_NEAR(measured, a, ref::rolling_resistance_tolerance * a);
  EXPECT_LT(std::abs(dot(p.velocity[0], cross(up, rolling_along))), 1e-9 * speed); // straight on
  // it stops and stays
  run_until(s, 1.5 * t_stop);
  EXPECT_LT(norm(p.velocity[0]), 1e-3 * speed);
  EXPECT_LT(norm(p.angular_velocity[0]) * rolling_radius, 1e-3 * speed);
}

TEST(RollingResistance3, RestsOnASlopeBelowItsAngleAndRollsDownAbove) {
  const double k = ref::sphere_inertia_factor;
  for (const double ratio : {0.8, 1.25}) { // tan alpha / mu_r
    const double slope = std::atan(ratio * rolling_mu_r);
    SCOPED_TRACE("tan(slope) / mu_r = " + std::to_string(ratio));
    Simulation3 s = roll_on_floor(0.0, slope);
    const Spheres& p = s.scene().spheres;
    const double t = 0.2;
    run_until(s, 0.5 * t);
    const double t1 = s.time(), v1 = dot(p.velocity[0], rolling_along);
    run_until(s, t);
    const double measured = (dot(p.velocity[0], rolling_along) - v1) / (s.time() - t1);
    const double expected =
        ratio < 1.0 ? 0.0
                    : rolling_g * (std::sin(slope) - rolling_mu_r * std::cos(slope)) / (1.0 + k);
    // at rest: what is left of the springs' ringing as the sphere settles (as in 2D)
    const double scale = rolling_g * std::sin(slope) / (1.0 + k);
    EXPECT_NEAR(measured, expected,
                ratio < 1.0 ? 1e-4 * scale : ref::rolling_resistance_tolerance * expected);
  }
}

// Two touching spheres spinning the same way about a tilted axis in free space: the rolling
// torques on them are opposite (angular momentum about the pair's centre is kept to rounding),
// and the relative spin in the tangent plane is what they resist.
TEST(RollingResistance3, TheTorquesOnTwoSpheresAreOpposite) {
  Material m = testing::elastic_material(1.0e6);
  m.rolling_friction = rolling_mu_r;
  Scene3 scene;
  scene.materials = {m};
  const Vec3 axis = (1.0 / std::sqrt(3.0)) * Vec3{1.0, 1.0, 1.0};
  scene.add_sphere(
      {.position = {0.0, 0.0, 0.0}, .radius = rolling_radius, .angular_velocity = 20.0 * axis});
  scene.add_sphere({.position = {2.0 * rolling_radius - 1e-5, 0.0, 0.0},
                    .radius = rolling_radius,
                    .angular_velocity = -20.0 * axis});
  const double mass = shape_mass(Shape::sphere, rolling_radius, m.density);
  Simulation3 s(std::move(scene),
                {.timestep = linear_collision_time(m.normal_stiffness, 0.0, mass) / 50.0,
                 .tangential_law = law_id<CundallStrack>});
  s.step();
  const Spheres& p = s.scene().spheres;
  const Vec3 total = p.torque[0] + p.torque[1];
  EXPECT_GT(norm(p.torque[0]), 0.0);
  EXPECT_LT(norm(total), 1e-12 * norm(p.torque[0]));
  EXPECT_LT(std::abs(p.torque[0].x), 1e-12 * norm(p.torque[0])); // none about the normal
}

} // namespace
} // namespace talus
