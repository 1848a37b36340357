#pragma once
// A scene of spheres in 3D and the settings of its run: what Simulation3 is built from.
#include <optional>
#include <vector>

#include "core/vec3.hpp"
#include "drivers/cell_of.hpp"

#include "engine3d/plate_drivers.hpp"
#include "engine3d/plate_servo.hpp"
#include "engine3d/spheres.hpp"
#include "integrate/integrator.hpp"
#include "materials/material.hpp"
#include "talus/contact_geometry.hpp"
#include "talus/law_table.hpp"

namespace talus {

struct Scene3 {
  Spheres spheres;
  std::vector<Plane> plates;
  std::vector<PlateDriver> drivers; ///< the plates' prescribed motions, from the run's start
  std::vector<PlateServo> servos;   ///< plates held at a load, each moved by its controller
  /// the periodic box deforming, its state with it (engine3d/cell3.hpp); none: a box that stays
  std::optional<CellOf<Vec3>> cell;
  Domain3 domain;
  std::vector<Material> materials{Material{}};
  Vec3 gravity{}; ///< m/s^2

  /// Adds a sphere; mass 4/3 pi r^3 rho from its material's density and inertia 2/5 m r^2
  /// unless given. Returns its index.
  std::size_t add_sphere(SphereSpec spec);
};

struct Settings3 {
  double timestep = 0.0;                      ///< s, required
  Integrator integrator = Integrator::verlet; ///< velocity Verlet, or the thesis' Gear
  NormalLaw normal_law = law_id<LinearSpringDashpot>;
  TangentialLaw tangential_law = law_id<CundallStrack>;
  VerletVelocity verlet_velocity = VerletVelocity::predicted; ///< as in 2D
  double skin = 0.0;                                          ///< m; 0: half the largest radius
  /// m/s: the impact speed at which a Hertz damping derived from the restitution reaches it
  double impact_speed = 1.0;
  LeverArm lever_arm = LeverArm::contact_point;
  LinearDamping linear_damping = LinearDamping::never_attractive;
  /// Stability guard: the run stops when an overlap exceeds this fraction of the smaller radius.
  double max_overlap_fraction = 0.5;
  /// Every this many steps (at the start of a step whose count is a multiple) the spheres are
  /// renumbered in the order of the cells they lie in (renumber3.hpp); 0: never. Sphere indices
  /// change then (ids do not).
  std::uint64_t sort_interval = 0;
  /// 0: all cores. Results are bit-identical for any count; fewer are taken for a small scene
  /// (Simulation3::threads).
  int threads = 0;
};

} // namespace talus
