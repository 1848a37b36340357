#pragma once
// A scenario of spheres in 3D (simulation.dimension = 3), typed and in SI units with every
// default filled: what the 3D engine has (docs/scenarios.md, "Spheres in 3D"). The loader
// (file/load3.hpp) makes one from TOML; build3.hpp makes a Scene3 from one.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/vec3.hpp"
#include "integrate/integrator.hpp"
#include "materials/material.hpp"
#include "scenario/scenario.hpp"
#include "talus/law_table.hpp"
#include "talus/plate.hpp"
#include "talus/timestep_advice.hpp"

namespace talus {

struct Simulation3Section {
  double duration = 1.0;          ///< s
  std::optional<double> timestep; ///< s; empty: "auto"
  Integrator integrator = Integrator::verlet;
  double timestep_factor = default_timestep_factor; ///< auto timestep = shortest t_c / factor
  VerletVelocity verlet_velocity = VerletVelocity::predicted;
  LeverArm lever_arm = LeverArm::contact_point;
  LinearDamping linear_damping = LinearDamping::never_attractive;
  NormalLaw normal_law = law_id<LinearSpringDashpot>;
  TangentialLaw tangential_law = law_id<CundallStrack>;
  Vec3 gravity{0.0, 0.0, -9.81}; ///< m/s^2
  std::uint64_t seed = 1;
  int threads = 0;                               ///< 0: all cores (results identical for any count)
  double skin = 0.0;                             ///< m; 0: half the largest radius
  std::uint64_t sort_every = default_sort_every; ///< steps between renumberings; 0: never
  double impact_speed = 1.0;                     ///< m/s: reference speed for Hertz collision times
};

struct Particles3Section {
  std::size_t count = 0;
  SizeSpec size;
  std::string material;
};

/// A box of plates: a face on each side of every axis that does not wrap, the top (z = hi)
/// left out when open_top.
struct Box3Section {
  Vec3 lo{0.0, 0.0, 0.0};
  Vec3 hi{0.05, 0.05, 0.1};
  std::array<bool, 3> periodic{false, false, false};
  bool open_top = true;
  /// a layer of fixed spheres glued on the floor (a rough base; not with periodic z)
  bool rough_floor = false;
  std::string wall_material;
};

/// A [[drivers]] entry: a prescribed motion of a group of the box's plates, each plate from
/// where it stands at the run's start (talus/plate.hpp moves it).
struct Driver3Section {
  bool servo = false; ///< a servo holding its plate at a load (the keys below); else `motion`
  bool cell = false;  ///< the periodic box deforming (engine3d/cell3.hpp; no target); else above
  PlateDriver::Motion motion = PlateDriver::Motion::translate;
  std::string target = "walls";  ///< "walls" (every plate) or one side: box3_sides() names them
  double amplitude = 0.0;        ///< vibrate: m
  double frequency = 0.0;        ///< vibrate: Hz
  double phase = 0.0;            ///< vibrate: rad
  Vec3 direction{0.0, 0.0, 1.0}; ///< vibrate: along it
  Vec3 velocity{};               ///< translate: m/s
  Vec3 centre{};                 ///< rotate: a point of the axis, m
  Vec3 angular_velocity{};       ///< rotate: rad/s, along the axis
  double force = 0.0;            ///< servo: N, the load wanted (or 0 with a stress)
  double stress = 0.0;           ///< servo: Pa, the load per area of the box's face (or 0)
  double max_speed = 0.0;        ///< servo: m/s, its fastest either way (simulation.impact_speed)
  double relaxation = 0.5;       ///< servo, cell: the fraction of the error closed per step
  Vec3 strain_rate{};            ///< cell: 1/s, the true strain rate of each side
  double pressure = 0.0;         ///< cell: Pa, the mean stress held (sheared: sigma_yy), or 0
  double max_strain_rate = 0.0;  ///< cell: 1/s, the pressure mode's fastest rate
  double shear_rate = 0.0;       ///< cell: 1/s, dv_x/dy of the images across y (Lees-Edwards)
};

/// A box of space [lo, hi), m.
struct Region3 {
  Vec3 lo{};
  Vec3 hi{};
};

/// A named region whose stress thermo.csv records (output.stress_regions), its columns prefixed
/// with the name and _.
struct StressRegion3 {
  std::string name;
  Region3 region;
};

struct Output3Section {
  double thermo_interval = 0.01;    ///< s
  double snapshot_interval = 0.1;   ///< s; 0: none
  double checkpoint_interval = 1.0; ///< s; 0: only at the end, at --stop-at and on a signal
  bool energy_ledger = false;       ///< the ledger's columns in thermo.csv (energy_ledger3.hpp)
  /// thermo.csv's stress, fabric and structure columns over `stress_region`, and each sphere's
  /// stress in the snapshots (stress3.hpp, structure3.hpp)
  bool stress = false;
  std::optional<Region3> stress_region;      ///< default: the geometry's box
  std::vector<StressRegion3> stress_regions; ///< more regions, each with its own columns
};

struct Scenario3 {
  std::string name = "scenario";
  std::string description;
  Simulation3Section simulation;
  std::vector<Material> materials;
  Particles3Section particles;
  Box3Section geometry;
  std::vector<Driver3Section> drivers;
  Output3Section output;
};

} // namespace talus
