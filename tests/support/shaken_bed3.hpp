#pragma once
// A bed of 300 spheres falling in a box periodic along x onto a floor vibrating at 50 Hz, with
// friction and rolling resistance: a 3D scene that exercises springs, rolling springs, a driven
// plate and periodic images at once (the 3D checkpoint and energy ledger tests).
#include "engine3d/simulation3.hpp"
#include "support/two_body.hpp"

namespace talus::testing {

/// The bed with the floor's amplitude (m), the timestep a linear collision time over
/// `steps_per_collision`, renumbered every 1000 steps.
inline Simulation3 shaken_bed3(Integrator integrator, double amplitude = 2e-4,
                               double steps_per_collision = 30.0) {
  Material m = elastic_material();
  m.restitution = 0.5;
  m.friction = 0.4;
  m.rolling_friction = 0.05;
  Scene3 scene;
  scene.materials = {m};
  scene.gravity = {0.0, 0.0, -9.81};
  scene.domain = {.lo = {0.0, 0.0, 0.0}, .hi = {0.02, 0.02, 0.2}, .periodic = {true, false, false}};
  scene.plates.push_back(make_plane({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}));
  scene.plates.push_back(make_plane({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}));
  scene.plates.push_back(make_plane({0.0, 0.02, 0.0}, {0.0, -1.0, 0.0}));
  scene.drivers.push_back({.plate = 0,
                           .motion = PlateDriver::Motion::vibrate,
                           .amplitude = amplitude,
                           .frequency = 50.0});
  for (int k = 0; k < 300; ++k)
    scene.add_sphere({.position = {0.002 + 0.004 * (k % 5), 0.002 + 0.004 * ((k / 5) % 5),
                                   0.002 + 0.004 * (k / 25)},
                      .radius = 1.5e-3 + 1e-4 * (k % 3),
                      .velocity = {0.2 * ((k % 7) - 3), 0.0, 0.0}});
  const double mass = 2650.0 * 4.0 / 3.0 * 3.14159 * 1.5e-9;
  return Simulation3(
      std::move(scene),
      {.timestep = linear_collision_time(m.normal_stiffness, 0.0, mass) / steps_per_collision,
       .integrator = integrator,
       .sort_interval = 1000}); // renumbered at the checkpoint test's step too
}

} // namespace talus::testing
