#pragma once
// The native 3D engine beside LAMMPS in the 3D agreement tests: the same spheres as a Scene3,
// run with LAMMPS' half-step damper velocity, and the largest differences between the two.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine3d/simulation3.hpp"
#include "spheres3d.hpp"

namespace talus::lammps_test {

// Two spheres 0.2 um apart, closing at 0.2 m/s off centre, out of any axis' plane, both spinning
// about tilted axes: the contact slides, sticks and ends within the steps.
inline std::vector<Sphere> oblique_pair() {
  const Vec3 offset{0.0, 0.0012, -0.0009}; // across the line of approach
  const double reach = 0.005 + 0.004 + 2e-7;
  const double along = std::sqrt(reach * reach - norm2(offset));
  return {{{0.0, 0.0, 0.0}, {0.1, 0.0, 0.0}, {10.0, -20.0, 30.0}, 0.005, 2.0e-4},
          {Vec3{along, 0.0, 0.0} + offset, {-0.1, 0.0, 0.0}, {-5.0, 0.0, 8.0}, 0.004, 1.5e-4}};
}

/// The side of periodic_cloud's box, m.
inline constexpr double cloud_side = 0.03;

// Twelve spheres thrown at each other in a box of side cloud_side periodic along x, y and z,
// moving and spinning about every axis, apart on a lattice of 2 x 2 x 3 sites, the lowest and
// the highest close across z's sides.
inline std::vector<Sphere> periodic_cloud() {
  RandomStream rng(2026, 1206);
  std::vector<Sphere> spheres;
  const double side = cloud_side;
  for (int k = 0; k < 12; ++k) {
    Sphere s{};
    s.radius = 0.003 * (1.0 + 0.2 * rng.uniform(-1.0, 1.0));
    s.mass = 1e-4 * (1.0 + 0.3 * rng.uniform(-1.0, 1.0));
    s.position = {side * (k % 2 == 0 ? 0.25 : 0.75) + 0.001 * rng.uniform(-1.0, 1.0),
                  side * ((k / 2) % 2 == 0 ? 0.25 : 0.75) + 0.001 * rng.uniform(-1.0, 1.0),
                  side * (0.15 + 0.35 * (k / 4)) + 0.001 * rng.uniform(-1.0, 1.0)};
    s.velocity = {rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)};
    s.spin = {50.0 * rng.uniform(-1.0, 1.0), 50.0 * rng.uniform(-1.0, 1.0),
              50.0 * rng.uniform(-1.0, 1.0)};
    spheres.push_back(s);
  }
  return spheres;
}

/// The spheres as a native scene of one material (no gravity, no plates).
inline Scene3 native_scene(const Material& m, const std::vector<Sphere>& spheres,
                           const Domain3& domain = {}) {
  Scene3 scene;
  scene.materials = {m};
  scene.domain = domain;
  for (const Sphere& s : spheres)
    scene.add_sphere({.position = s.position,
                      .radius = s.radius,
                      .velocity = s.velocity,
                      .angular_velocity = s.spin,
                      .mass = s.mass});
  return scene;
}

/// Native velocity Verlet with LAMMPS' velocity convention (the dampers see the half-step
/// velocity, as under fix nve/sphere), the laws by name.
inline Simulation3 run_as_lammps(Scene3 scene, const std::string& normal,
                                 const std::string& tangential, double dt) {
  return Simulation3(std::move(scene), {.timestep = dt,
                                        .normal_law = parse_normal_law(normal),
                                        .tangential_law = parse_tangential_law(tangential),
                                        .verlet_velocity = VerletVelocity::half_step});
}

struct Difference {
  double position = 0.0; ///< the largest component of a position's difference, m
  double velocity = 0.0; ///< m/s
  double spin = 0.0;     ///< rad/s
};

/// The largest differences between the engines, positions taken to their nearest image.
inline Difference between(LammpsInstance& l, const Simulation3& s) {
  const Spheres& p = s.scene().spheres;
  const Domain3& d = s.scene().domain;
  Difference out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int id = static_cast<int>(p.id[i]) + 1; // LAMMPS' ids: the native ids + 1
    const double* w = l.lmp()->atom->omega[l.index(id)];
    for (int k = 0; k < 3; ++k) {
      const auto axis = static_cast<std::size_t>(k);
      double dx = l.position(id)[k] - component(p.position[i], k);
      if (d.periodic[axis]) {
        const double length = component(d.size(), k);
        dx -= length * std::nearbyint(dx / length);
      }
      out.position = std::max(out.position, std::abs(dx));
      out.velocity =
          std::max(out.velocity, std::abs(l.velocity(id)[k] - component(p.velocity[i], k)));
      out.spin = std::max(out.spin, std::abs(w[k] - component(p.angular_velocity[i], k)));
    }
  }
  return out;
}

} // namespace talus::lammps_test
