// One grain against a rigid floor of its own material, no gravity: the harness of the
// single-contact tests (friction's energy, oblique impacts against their theory).
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include "simulation/simulation.hpp"
#include "talus/law_table.hpp"

namespace talus::single_impact {

struct Impact {
  Material grain;
  NormalLaw normal = law_id<HertzViscoelastic>;
  TangentialLaw tangential = law_id<CundallStrack>;
  Shape shape = Shape::sphere;
  double radius = 0.1;
  Vec2 velocity{};
  double spin = 0.0;
  double steps_per_collision = 50.0;
  LeverArm arm = LeverArm::contact_point;
  Integrator integrator = Integrator::gear;
};

// A rigid floor of the grain's own material.
inline Material floor_of(const Material& grain) {
  Material wall = grain;
  wall.name = "floor";
  wall.rigid = true;
  return wall;
}

// The grain's collision time against the rigid floor at its normal speed.
inline double collision_time(const Impact& c, double mass) {
  const PairParameters p = mix(c.grain, floor_of(c.grain), std::abs(c.velocity.y));
  return with_normal_law(c.normal, [&]<class N>() {
    return N::collision_time(p, mass, c.radius, std::abs(c.velocity.y));
  });
}

// A grain just above a rigid floor (y = 0) of its own material, moving and spinning as asked, no
// gravity: the grain's force is the floor's contact force alone.
inline Simulation impact(const Impact& c) {
  World w;
  w.materials = {c.grain, floor_of(c.grain)};
  w.add_particle({.position = {0.0, c.radius * 1.0001},
                  .radius = c.radius,
                  .shape = c.shape,
                  .velocity = c.velocity});
  w.particles.angular_velocity[0] = c.spin;
  w.add_wall({-100.0 * c.radius, 0.0}, {100.0 * c.radius, 0.0}, 1);
  SimulationConfig config;
  config.normal_law = c.normal;
  config.tangential_law = c.tangential;
  config.lever_arm = c.arm;
  config.integrator = c.integrator;
  config.impact_speed = std::abs(c.velocity.y);
  config.timestep = collision_time(c, w.particles.mass[0]) / c.steps_per_collision;
  return Simulation(std::move(w), config);
}

inline double gap(const Simulation& s) {
  const auto& p = s.world().particles;
  return p.position[0].y - p.radius[0];
}

// The slip velocity of the grain's contact point against the floor (along +x).
inline double slip(const Simulation& s, LeverArm arm) {
  const auto& p = s.world().particles;
  const double overlap = std::max(0.0, -gap(s));
  const double lever = p.radius[0] - lever_shares(arm).torque * overlap;
  return p.velocity[0].x + p.angular_velocity[0] * lever;
}

} // namespace talus::single_impact
