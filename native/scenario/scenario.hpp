#pragma once
// A whole experiment, typed and in SI units, as a scenario file describes it (every default
// filled). The loader (load.hpp) makes one from TOML; build.hpp makes a World from one.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/vec2.hpp"
#include "integrate/integrator.hpp"
#include "materials/material.hpp"
#include "state/particles.hpp"
#include "talus/law_table.hpp"
#include "talus/timestep_advice.hpp"

namespace talus {

struct Rect {
  Vec2 lo;
  Vec2 hi;
  friend bool operator==(const Rect&, const Rect&) = default;
};

/// Steps between renumberings of the grains in the order of their cells, unless a scenario
/// says (simulation.sort_every).
inline constexpr std::uint64_t default_sort_every = 1000;

struct SimulationSection {
  double duration = 1.0;                            ///< s
  std::optional<double> timestep;                   ///< s; empty: "auto"
  double timestep_factor = default_timestep_factor; ///< auto timestep = shortest t_c / factor
  Integrator integrator = Integrator::gear;
  VerletVelocity verlet_velocity = VerletVelocity::predicted; ///< velocity Verlet's damper velocity
  LeverArm lever_arm = LeverArm::contact_point; ///< the contacts' lever arms (contact_geometry.hpp)
  /// the linear law's damping convention (talus/pair_parameters.hpp)
  LinearDamping linear_damping = LinearDamping::never_attractive;
  NormalLaw normal_law = law_id<LinearSpringDashpot>;
  TangentialLaw tangential_law = law_id<CundallStrack>;
  Vec2 gravity{0.0, -9.81}; ///< m/s^2
  std::uint64_t seed = 1;
  int threads = 0;                               ///< 0: all cores
  double skin = 0.0;                             ///< m; 0: automatic
  std::uint64_t sort_every = default_sort_every; ///< steps between renumberings; 0: never
  double impact_speed = 1.0;                     ///< m/s: reference speed for Hertz collision times
};

struct SizeSpec {
  std::string distribution = "uniform"; ///< uniform | wentworth | discrete
  double mean_radius = 5.0e-3;          ///< m (uniform)
  double spread = 0.0;                  ///< m: radii uniform in mean +- spread (uniform)
  std::string wentworth_class;          ///< e.g. "coarse sand" (wentworth)
  std::vector<double> radii;            ///< m (discrete)
  std::vector<double> fractions;        ///< number fractions, sum 1 (discrete)
};

struct ExplicitParticle {
  Vec2 position;
  double radius = 0.0;
  Vec2 velocity{};
  double angular_velocity = 0.0;
  double mass = 0.0; ///< 0: from shape and density
  std::string kind = "free";
  std::string group = "fixed"; ///< a fixed grain's wall group
  std::string material;
};

struct ParticlesSection {
  std::size_t count = 0;
  Shape shape = Shape::sphere;
  std::string material;
  SizeSpec size;
  std::vector<ExplicitParticle> list; ///< placed as given, before the counted grains
};

struct PackingSection {
  std::string method = "lattice"; ///< lattice | random | sedimentation
  std::optional<Rect> region;     ///< where grains are placed; default: the geometry's fill region
  double settle_energy = 1.0e-6;  ///< sedimentation ends when E_kin < this x sum(m g R)
  double settle_max_time = 5.0;   ///< s
};

struct SegmentSpec {
  Vec2 a;
  Vec2 b;
  std::string group = "extra"; ///< the wall group it joins (driven, measured by this name)
  friend bool operator==(const SegmentSpec&, const SegmentSpec&) = default;
};

struct GeometrySection {
  std::string builder =
      "none";          ///< none | box | silo | window_box | hopper | hourglass | grain_press | drum
  double width = 0.0;  ///< m
  double height = 0.0; ///< m
  double orifice = 0.0;            ///< m (hopper, hourglass; silo: 0 for a closed floor)
  std::optional<double> orifice_x; ///< m: the orifice's centre (silo; default width / 2)
  std::optional<double> bin_depth; ///< m: the bin below the orifice (silo, hopper)
  double wall_angle = 60.0;        ///< degrees from horizontal (hopper, hourglass)
  /// The orifice closed by a gate, the wall group "gate", after the packing too, until a driver
  /// moves it away (a stage that slides it open). Silo with an orifice, hopper, hourglass.
  bool gate = false;
  double lid_speed = 0.0;            ///< m/s downward, negative upward (grain_press)
  double radius = 0.0;               ///< m (drum)
  double angular_velocity = 0.0;     ///< rad/s (drum)
  std::string walls = "segments";    ///< segments | particles
  double wall_particle_radius = 0.0; ///< m; 0: the smallest grain radius
  std::string wall_material;
  std::string periodic = "none";     ///< none | x | y | xy
  std::optional<Rect> box;           ///< the periodic box
  std::vector<SegmentSpec> segments; ///< extra walls
};

struct DriverSection {
  std::string type;             ///< vibrate | translate | rotate | servo | cell
  std::string target = "walls"; ///< a wall group of the geometry ("" for a cell)
  double amplitude = 0.0;       ///< m
  double frequency = 0.0;       ///< Hz
  double phase = 0.0;           ///< rad
  Vec2 direction{0.0, 1.0};
  Vec2 velocity{};               ///< m/s
  Vec2 centre{};                 ///< m
  double angular_velocity = 0.0; ///< rad/s
  double force = 0.0;            ///< servo: N, the load wanted
  double stress = 0.0;           ///< servo: N/m, the load per width of the walls (or force)
  double max_speed = 0.0;        ///< servo: m/s (simulation.impact_speed unless given)
  double relaxation = 0.5;       ///< servo: the fraction of the load's error closed per step
  double slide_speed = 0.0;      ///< servo: m/s across direction (a quarter turn anticlockwise)
  Vec2 strain_rate{};            ///< cell: 1/s, the rate mode's d(ln L)/dt along x and y
  double pressure = 0.0;         ///< cell: N/m, the pressure mode's target (0: rate mode)
  double max_strain_rate = 0.0;  ///< cell: 1/s, the pressure mode's fastest rate
  double shear_rate = 0.0;       ///< cell: 1/s, dv_x/dy of the Lees-Edwards images (0: none)
};

struct TrackSection {
  std::vector<std::uint32_t> ids;
  std::string select = "none"; ///< none | largest | smallest | nearest
  Vec2 at{};                   ///< nearest to this point
  std::size_t count = 1;
};

/// A named region whose stress thermo.csv records (output.stress_regions).
struct StressRegion {
  std::string name;
  Rect region;
  friend bool operator==(const StressRegion&, const StressRegion&) = default;
};

struct OutputSection {
  double thermo_interval = 0.01;    ///< s
  double snapshot_interval = 0.1;   ///< s; 0: none
  double checkpoint_interval = 1.0; ///< s; 0: only at the end
  double track_interval = 0.001;    ///< s
  bool thesis_out = false;          ///< also write the thesis' .out snapshots
  /// Each snapshot's touching contacts as CSV, and every contact's start, end and peaks in
  /// contact_events.csv (the contacts are then looked at every step).
  bool contacts = false;
  /// The energy ledger in thermo.csv: the energy dissipated by the dampers and by friction, the
  /// driven walls' work, and the balance's error (the contacts are then looked at every step).
  bool energy_ledger = false;
  /// The stress of the grains in thermo.csv (contact and kinetic parts, principal values, the
  /// fabric) over `stress_region`, and each grain's stress in the snapshots.
  bool stress = false;
  std::optional<Rect> stress_region;        ///< default: the container's extent
  std::vector<StressRegion> stress_regions; ///< more regions, each with its own columns
  bool picture = true;                      ///< final.png at the end
  /// Pictures of the last snapshot at the end of the run, into pictures/: each "COLOUR" with
  /// optional "+chains" and "+tracks", e.g. "force+chains" (see PictureRequest).
  std::vector<std::string> pictures;
  bool movie = false;                ///< movie.mp4 of all snapshots at the end (needs ffmpeg)
  std::string movie_color = "speed"; ///< the movie's colour field
};

/// Frost heave. "uniform": the thesis' rule (sec. 5.2): whenever the kinetic energy falls below
/// kinetic_threshold x sum(m g R) and at least min_interval has passed since the last freeze,
/// every free grain's height above the floor is multiplied by heave_factor. "front": a freezing
/// front descends column by column and heaves the frozen crust, then a thaw front releases it
/// (frost/frost_front.hpp); a cycle starts when the grains are at rest, as above.
struct FrostSection {
  std::string model = "none"; ///< none | uniform | front
  double heave_factor = 1.5;
  double kinetic_threshold = 1.0e-6; ///< x sum(m g R) of the free grains
  double min_interval = 0.05;        ///< s
  std::size_t cycles = 0;            ///< stop after this many cycles (0: run to duration)
  // the front model
  double permafrost_depth = 0.0;   ///< m below the surface
  double heave_strain = 0.1;       ///< heave per unit depth of frozen fines
  double conductivity_ratio = 3.0; ///< stone / soil
  double stone_water = 0.0;        ///< stone / soil latent heat per volume
  double ice_content = 0.0;        ///< ice per volume of frozen fines (0: their pore fraction)
  double crust_length = 0.0;       ///< m (0: the column width)
  double column_width = 0.0;       ///< m (0: the largest stone's diameter)
  double stone_radius = 0.0;       ///< m (0: 1.5 x the median radius)
  double freeze_time = 0.5;        ///< s
  double thaw_time = 0.5;          ///< s
  bool frost_pull = true;          ///< stones are released when their lowest point thaws
  std::string thawed_material;     ///< thawed fines take this material ("": unchanged)
};

/// One stage of an experiment run in stages ([[stages]]: settle, then tilt; fill, then open):
/// it starts where the one before ended, with the changes of `set`, and ends after `duration`
/// or, first, when its condition `until` holds (looked at with every thermo row). The last stage
/// lasts to the run's end (simulation.duration: the sum of the stages' unless given; a shorter
/// one ends the run before the later stages) or to its condition, which then ends the run.
struct StageSection {
  std::string name;
  double duration = 0.0; ///< s: the longest the stage lasts
  /// none | settled | kinetic_below | kinetic_above (kinetic) | wall_force_above (group, force)
  /// | wall_position_below | wall_position_above (group, position) | grains_below (height, count)
  std::string until = "none";
  double kinetic = 0.0;         ///< J: the kinetic energy's threshold
  std::string group;            ///< a wall group of the geometry (wall_* conditions)
  double force = 0.0;           ///< N: the magnitude of the grains' force on the group
  double position = 0.0;        ///< m: the group's height (the mean y of its walls and particles)
  double height = 0.0;          ///< m: grains_below counts the free grains below this height
  std::size_t count = 0;        ///< grains_below: this many
  std::string then = "next";    ///< when the condition holds: next (the next stage) | end (the run)
  std::vector<std::string> set; ///< "key=value" changes at the stage's start (as --set)
};

struct Scenario {
  std::string name = "scenario";
  std::string description;
  SimulationSection simulation;
  std::vector<Material> materials;
  ParticlesSection particles;
  PackingSection packing;
  GeometrySection geometry;
  std::vector<DriverSection> drivers;
  TrackSection track;
  OutputSection output;
  FrostSection frost;
  std::vector<StageSection> stages; ///< empty: one stage, the whole run
};

} // namespace talus
