// A grain sliding on a flat floor: friction turns sliding into rolling at the classical point.
#include <gtest/gtest.h>

#include <cmath>

#include "materials/timestep.hpp"
#include "physics/reference_values.hpp"
#include "support/two_body.hpp"

namespace talus {
namespace {

struct RollCase {
  Shape shape;
  TangentialLaw law;
  Integrator integrator;
};

class Rolling : public ::testing::TestWithParam<RollCase> {};

TEST_P(Rolling, StartsToRollAtTheClassicalSpeedAndTime) {
  const RollCase rc = GetParam();
  const double r = 5.0e-3, v0 = 0.5, mu = 0.3, g = 9.81;
  Material m = testing::elastic_material(1.0e6);
  m.restitution = 0.3; // settles the floor contact quickly
  m.friction = mu;
  m.tangential_damping = 2000.0; // 1/s: strong viscous slip resistance, Coulomb-limited
  World w;
  w.materials = {m};
  w.gravity = {0.0, -g};
  w.add_wall({-1.0, 0.0}, {10.0, 0.0});
  const double mass = shape_mass(rc.shape, r, m.density);
  const double sag = mass * g / m.normal_stiffness; // resting overlap
  w.add_particle(
      {.position = {0.0, r - sag}, .radius = r, .shape = rc.shape, .velocity = {v0, 0.0}});

  SimulationConfig c;
  c.timestep = linear_collision_time(m.normal_stiffness, 0.0, mass) / 50.0;
  c.normal_law = law_id<LinearSpringDashpot>;
  c.tangential_law = rc.law;
  c.integrator = rc.integrator;
  Simulation s(std::move(w), c);

  const bool disk = rc.shape == Shape::disk;
  const double t_ref =
      (disk ? reference::disk_roll_time_factor : reference::sphere_roll_time_factor) * v0 /
      (mu * g);
  const double v_ref =
      (disk ? reference::disk_roll_speed_ratio : reference::sphere_roll_speed_ratio) * v0;
  const auto& p = s.world().particles;
  // rolling begins when the contact point's slip falls below 1% of v0
  double t_roll = -1.0, v_roll = 0.0;
  while (s.time() < 2.0 * t_ref) {
    s.step();
    const double slip = p.velocity[0].x + p.angular_velocity[0] * p.radius[0];
    if (std::abs(slip) < 0.01 * v0) {
      t_roll = s.time();
      v_roll = p.velocity[0].x;
      break;
    }
  }
  ASSERT_GT(t_roll, 0.0) << "never started to roll";
  EXPECT_NEAR(t_roll, t_ref, t_ref * reference::rolling_tolerance);
  EXPECT_NEAR(v_roll, v_ref, v_ref * reference::rolling_tolerance);
  // and it keeps rolling without slip at that speed
  for (int k = 0; k < 2000; ++k) s.step();
  EXPECT_NEAR(p.velocity[0].x, v_ref, v_ref * reference::rolling_tolerance);
}

INSTANTIATE_TEST_SUITE_P(
    ShapesAndLaws, Rolling,
    ::testing::Values(RollCase{Shape::disk, law_id<ViscousCoulomb>, Integrator::gear},
                      RollCase{Shape::disk, law_id<CundallStrack>, Integrator::gear},
                      RollCase{Shape::sphere, law_id<CundallStrack>, Integrator::verlet},
                      RollCase{Shape::sphere, law_id<ViscousCoulomb>, Integrator::verlet}),
    [](const auto& param_info) {
      return std::string(param_info.param.shape == Shape::disk ? "disk_" : "sphere_") +
             std::string(name_of(param_info.param.law)) + "_" +
             std::string(to_string(param_info.param.integrator));
    });

} // namespace
} // namespace talus
