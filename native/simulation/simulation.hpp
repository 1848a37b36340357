#pragma once
// The facade a user drives: owns the World, runs the stages of a step, calls observers.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <limits>
#include <string>
#include <vector>

#include "core/contact_vectors.hpp"
#include "drivers/cell.hpp"
#include "drivers/servo.hpp"
#include "integrate/integrator.hpp"
#include "materials/pair_table.hpp"
#include "neighbours/neighbour_list.hpp"
#include "simulation/force_stage.hpp"
#include "simulation/step_features.hpp"
#include "simulation/world.hpp"
#include "talus/law_table.hpp"
#include "talus/segment_contact.hpp"

namespace talus {

struct SimulationConfig {
  double timestep = 0.0; ///< s, required
  Integrator integrator = Integrator::gear;
  NormalLaw normal_law = law_id<LinearSpringDashpot>;
  TangentialLaw tangential_law = law_id<CundallStrack>;
  VerletVelocity verlet_velocity = VerletVelocity::predicted; ///< velocity Verlet's damper velocity
  double skin = 0.0; ///< m; 0: automatic, chosen at every build (neighbours/skin.hpp)
  /// m/s: the impact speed at which a Hertz damping derived from the restitution reaches it
  double impact_speed = 1.0;
  int threads = 0; ///< 0: all cores (OpenMP default)
  /// Fewer particles than this per thread is not worth the threads' overhead: small systems
  /// use fewer threads (the results are bit-identical whatever the count).
  std::size_t min_particles_per_thread = 500;
  /// Stability guard: the run stops when an overlap exceeds this fraction of the smaller radius.
  double max_overlap_fraction = 0.5;
  /// Stability guard: the run stops when a free particle leaves [escape_lo, escape_hi] (checked
  /// every 16 steps; an empty box, the default, turns the check off). Periodic directions wrap.
  Vec2 escape_lo{};
  Vec2 escape_hi{};
  /// Every this many steps (at the start of a step whose count is a multiple), the particles
  /// are renumbered in the order of the cells they lie in (bands of cells, each row by row),
  /// so that neighbours lie close in memory as flow mixes the grains; 0: never. Particle
  /// indices change then (ids do not): see Simulation::renumberings.
  std::uint64_t sort_interval = 0;
  /// The lever arms of the contacts' torques and of the spin in their tangential velocity:
  /// contact_point (the default) or radius, LAMMPS' convention (talus/contact_geometry.hpp).
  LeverArm lever_arm = LeverArm::contact_point;
  /// the linear law's damping convention (pair_parameters.hpp)
  LinearDamping linear_damping = LinearDamping::never_attractive;
};

/// One touching contact, as the force stage sees it. `wall` is the segment index for a
/// particle-wall contact (then j is unused), or -1 for a particle pair.
struct ContactView {
  std::uint32_t i = 0;
  std::uint32_t j = 0;
  std::int32_t wall = -1;
  ContactGeometry geometry;
  const PairParameters* parameters = nullptr;
  double history = 0.0;
  double rolling = 0.0; ///< the rolling spring's angle, seen from i (0 without rolling resistance)
};

/// Everything that determines how a run continues: saved in checkpoints.
struct SimulationState {
  World world;
  NeighbourList neighbours;
  double time = 0.0;
  std::uint64_t steps = 0;
  /// The time (s) and step from which the timestep in force counts: t = clock_time + (steps -
  /// clock_step) dt. Both 0 unless the timestep changed during the run: a state restored with
  /// another timestep continues from where it is (the integrators keep their derivatives
  /// unscaled) with its clock set here to its time and step.
  double clock_time = 0.0;
  std::uint64_t clock_step = 0;
};

class ParticleEdits;

/// The steps until `time` (s) at a timestep `dt` (s), rounded up (a time a billionth of a step
/// past a whole count is that count); a count beyond any run is cut to one no run reaches.
std::uint64_t steps_until(double time, double dt);

/// The engine's memory by what it holds, bytes.
struct Footprint {
  std::size_t particles = 0;  ///< positions, velocities, forces, angles, spins, torques, radii,
                              ///< masses, inertia, materials, kinds, ids
  std::size_t integrator = 0; ///< Gear's higher derivatives, or Verlet's previous force and torque
  std::size_t list = 0;       ///< the neighbour list: rows, neighbours, images, build positions,
                              ///< deferred slots, wall entries
  std::size_t history = 0;    ///< the springs of the list's entries and of the wall contacts
  std::size_t candidates = 0; ///< the contact candidates (ContactCandidates)
  std::size_t other = 0;      ///< walls, driven particles, the force stage's slots and schedule
  std::size_t total() const { return particles + integrator + list + history + candidates + other; }
};

class Simulation {
public:
  /// Validates the setup (materials, laws, timestep) and computes the initial forces.
  Simulation(World world, SimulationConfig config);
  /// Continues from a saved state exactly: drivers keep their origins, forces, integrator
  /// derivatives and the neighbour list (with its build positions) are taken as saved, so the
  /// continuation is bit-identical to the run that was saved. `config.threads` may differ.
  static Simulation restore(SimulationState state, SimulationConfig config);
  /// A copy of the state, for a checkpoint.
  SimulationState state() const { return {world_, list_, time_, steps_, clock_time_, clock_step_}; }

  /// One time step: predict, move bodies, neighbours, contacts, correct, guard.
  void step();
  /// `steps` steps; `observer` (if any) is called every `every` steps after the step.
  void run(std::uint64_t steps, const std::function<void(const Simulation&)>& observer = {},
           std::uint64_t every = 1);

  double time() const { return time_; }
  std::uint64_t step_count() const { return steps_; }
  /// The step and time (s) from which the timestep in force counts (SimulationState).
  std::uint64_t clock_step() const { return clock_step_; }
  double clock_time() const { return clock_time_; }
  /// The first step at or after `time` (s) at the timestep in force, rounded up (steps_until).
  std::uint64_t step_at(double time) const;
  /// Between steps: removes the walls marked in `removed` (one flag per wall) and appends
  /// `added`. Returns each old wall's new index, or -1 where it was removed. Drivers' targets and
  /// the neighbour list's wall contacts follow (those of removed walls end, the others keep their
  /// springs); the list is built again before the next step's forces, so added walls are seen.
  /// Throws InvalidArgument for a removed wall that a driver moves.
  std::vector<std::int64_t> change_walls(const std::vector<bool>& removed, const Segments& added);
  /// Between steps: appends particles (mass and inertia resolved, free or fixed), each with a new
  /// id after the largest, and returns the index of the first. Their integrators' history is
  /// that of free flight (gravity's acceleration, Verlet's previous force m g). The neighbour
  /// list is built again at once, the other contacts keeping their springs. Throws InvalidArgument
  /// for a material out of range or a moved particle.
  std::size_t add_particles(const std::vector<ParticleSpec>& specs);
  /// Between steps: removes the free particles marked in `removed` (one flag per particle); the
  /// others keep their order, their ids and their contacts' springs (the list is built again at
  /// once), and the drivers' targets follow. Returns each old index's new one, or -1 where it was
  /// removed. Throws InvalidArgument for a wall or held particle marked.
  std::vector<std::int64_t> remove_particles(const std::vector<bool>& removed);
  const World& world() const { return world_; }
  /// Mutable access, for setting up or changing the world between steps (not while stepping).
  /// The next steps test the neighbour list against every particle's build position, since
  /// the caller may have moved particles.
  World& edit_world() {
    drift_bound_ = unknown_drift;
    features_stale_ = true;
    return world_;
  }
  const SimulationConfig& config() const { return config_; }
  const PairTable& pairs() const { return pairs_; }
  const NeighbourList& neighbours() const { return list_; }
  int threads() const { return threads_; }
  /// The threads the system's size pays for (the most use_threads takes).
  int max_threads() const { return max_threads_; }
  /// Between steps: the threads of the steps from now on, 1 to max_threads(). The results are
  /// the same bits whatever the count, so a run may change it as it goes
  /// (simulation/thread_chooser.hpp).
  void use_threads(int n) { threads_ = std::clamp(n, 1, max_threads_); }
  /// Between steps: edits of single particles that a model makes (frost holds grains, moves
  /// held ones and thaws them), with what the next steps must know of them.
  ParticleEdits edit_particles();
  /// Between steps: renumbers the particles in the order of the cells they lie in (as
  /// `sort_interval` does). The neighbour list, its history, the drivers' targets and the held
  /// particles follow; a caller that keeps particle indices maps them with new_indices().
  void sort_particles();
  /// How many times the particles were renumbered, and the new index of every old index at the
  /// last time (empty before).
  std::uint64_t renumberings() const { return renumberings_; }
  const std::vector<std::uint32_t>& new_indices() const { return new_of_old_; }
  /// How many times every particle was compared with its position at the neighbour list's build
  /// (only when the drift bound could have reached half the skin), and how many force stages
  /// chose the contact candidates again (ContactCandidates), since construction.
  std::uint64_t drift_tests() const { return drift_tests_; }
  std::uint64_t candidate_choices() const { return forces_.candidate_choices(); }
  /// Bytes the engine holds, by what for (allocated capacity, not the process' resident size).
  Footprint footprint() const;
  std::size_t footprint_bytes() const { return footprint().total(); }
  /// What the scene uses, and so what the step leaves out (step_features.hpp): chosen at the
  /// construction and again at the first step after the world or a particle was edited.
  const StepFeatures& step_features() const { return features_; }
  /// describe(step_features()): "frictionless, no walls, one material", or "general".
  std::string step_description() const { return describe(features_); }
  /// With `general`, every step does everything, whatever the scene uses (the reference the
  /// specialised steps are tested against: their results are bit-identical); else the step is
  /// specialised to the scene, the default.
  void use_general_step(bool general);
  /// Calls f for every touching contact (pairs in list order, then walls), for analysis.
  void for_each_contact(const std::function<void(const ContactView&)>& f) const;
  /// The deforming cell's driver (drivers.hpp, Cell), or nullptr: one at most.
  const Cell* cell_driver() const;
  /// The grains' mean stress and its stiffness as a cell held at a pressure reads them after a
  /// step (drivers/cell.hpp): from the contacts of the list and the free grains' velocities.
  CellReading cell_reading() const;

  /// A contact resolved in fewer steps than this is blamed on the timestep.
  static constexpr double min_steps_per_contact = 10.0;

private:
  friend class ParticleEdits;
  Simulation(SimulationState state, SimulationConfig config, bool restoring);
  /// One step: the stages of ../shared/DESIGN.md in order. With `fuse`, the correction of this
  /// step and the prediction of the next are done together (velocity Verlet: in the force stage,
  /// particle by particle; Gear: one pass), and the state between the two steps is the predicted
  /// one: run() fuses only where nothing looks at the state in between.
  void advance(bool fuse);
  /// Stage 1 (unless the last step's fused pass did it): the integrator's prediction, after the
  /// renumbering that sort_interval asks for. Returns whether some grain may have drifted more
  /// than half the skin since the list's build (the part of stage 3 the integrator's
  /// displacement answers; tested before the drivers move their particles).
  bool predict();
  /// Stage 2: the drivers move their particles and walls to time t.
  void move_bodies(double t);
  /// Stage 2 too: a deforming cell takes its strain for the step, and every grain and the
  /// list's build positions follow it affinely. Returns whether a gap may have closed by more
  /// than the skin allows since the list's build (the drift test with the strain's reserve).
  bool deform_cell();
  /// After stage 4: a cell held at a pressure reads the grains and takes its next rate.
  void drive_cell();
  Cell* mutable_cell(); ///< cell_driver(), to change its state
  /// cell_reserve_ from the box now and at the list's build, and the largest radius (m).
  void update_cell_reserve(double max_radius);
  /// The domain's Lees-Edwards velocity from the cell's shear rate and the height (0 without a
  /// cell): before the first force stage and at each step's strain.
  void set_shear_velocity();
  /// Before a build: the Lees-Edwards offset back into [0, L_x).
  void reduce_shear_offset();
  /// Stage 3: the neighbour list built again if a grain drifted, a held grain was freed, or a
  /// wall or driven particle moved more than half the skin.
  void update_neighbours(bool drifted);
  /// Stage 4: the contact forces; velocity Verlet's correction (and with `fuse` the next
  /// prediction) done in it, particle by particle. Stops the run on an overlap past the guard's
  /// limit while it is there.
  PassReport contacts(bool fuse);
  /// After stage 4: each servo reads its walls' load and contacts and takes its next speed
  /// (drivers/servo.hpp).
  void drive_servos();
  bool has_servo() const;
  /// Stage 5: the integrator's correction (and with `fuse` the next step's prediction).
  void correct(bool fuse, const PassReport& forces);
  /// Stage 6: the stability guard (non-finite state, overlap too deep, a grain escaped).
  void guard() const;
  void describe_deepest_contact(std::ostringstream& msg) const;
  void list_moved();        ///< driven_: every Kind::moved particle
  double next_skin() const; ///< the skin of the next list build (config or automatic)
  /// The neighbour list's drift test for the particles, after a pass that moved them at most
  /// sqrt(displacement2): has a grain moved more than half the skin since the build? Adds the
  /// displacement to drift_bound_ and compares the positions with the build's only when the
  /// bound could have reached half the skin.
  bool drifted(double displacement2);
  /// Builds the neighbour list again; the drift bound starts from 0 and the contact candidates
  /// are chosen again.
  void rebuild_list(int threads);
  /// Chooses the step's features from the scene (or all of them, for the general step) and
  /// makes the list keep the history they need, or none.
  void choose_features();

  World world_;
  SimulationConfig config_;
  PairTable pairs_;
  NeighbourList list_;
  ForceStage forces_;
  double time_ = 0.0;
  std::uint64_t steps_ = 0;
  double clock_time_ = 0.0;      ///< SimulationState::clock_time
  std::uint64_t clock_step_ = 0; ///< SimulationState::clock_step
  int threads_ = 1;
  int max_threads_ = 1;
  bool finite_ = true;                ///< every position and velocity finite after the last step
  std::vector<std::uint32_t> driven_; ///< moved particles, by drivers or held (drift checked)
  std::uint64_t renumberings_ = 0;
  std::vector<std::uint32_t> new_of_old_;
  bool driven_stale_ = false;            ///< a particle was held or freed since driven_ was listed
  bool list_stale_ = false;              ///< a held particle was freed: rebuild the list
  bool predicted_ = false;               ///< the next step's prediction is done (only inside run())
  double predicted_displacement2_ = 0.0; ///< and how far it moved the farthest particle
  /// An upper bound of how far any free particle moved since the list's build (m): the sum of
  /// the largest displacement of every pass over the particles since then. Every particle is
  /// compared with its build position only once this bound could have reached half the skin,
  /// which gives the same answers as comparing them at every step. Unknown (infinite) after a
  /// restore and after edit_world, until the next build. Driven particles are tested apart.
  static constexpr double unknown_drift = std::numeric_limits<double>::infinity();
  double drift_bound_ = unknown_drift;
  /// How far the deforming cell's strain since the list's build may have closed a gap (m): the
  /// drift test and the contact candidates leave it out of the skin (0 without a cell).
  double cell_reserve_ = 0.0;
  std::uint64_t drift_tests_ = 0;
  StepFeatures features_;
  /// drive_servos' part for the servos' wall particles: their contacts with grains.
  void read_servo_particles(std::vector<ServoReading>& reading);
  // drive_servos' scratch, kept so that a step allocates nothing: the servo owning each segment
  // and each particle (-1: none), each driver's reading, the wall contacts of one particle
  std::vector<std::int32_t> servo_owner_;
  std::vector<std::int32_t> servo_particle_owner_;
  std::vector<ServoReading> servo_reading_;
  std::vector<SegmentHit> servo_hits_;
  bool features_stale_ = false; ///< the world or a particle was edited since they were chosen
  bool general_step_ = false;
};

/// Edits of single particles between steps (Simulation::edit_particles), for a model that
/// changes grains as it goes: frost holds grains in place, moves held ones and thaws them.
class ParticleEdits {
public:
  /// Holds particle i at rest (not integrated; free grains still feel it) or frees it. Its drift
  /// is then checked against the neighbour list like a driven particle's.
  void hold(std::uint32_t i, bool held);
  /// Particle i is made of material m from now on; throws InvalidArgument for a material index
  /// out of range.
  void set_material(std::uint32_t i, std::size_t m);
  /// Moves a held particle by d (m); throws std::logic_error for a free one.
  void displace_held(std::uint32_t i, Vec2 d);

private:
  friend class Simulation;
  explicit ParticleEdits(Simulation& sim) : sim_(sim) {}
  Simulation& sim_;
};

inline ParticleEdits Simulation::edit_particles() {
  return ParticleEdits(*this);
}

} // namespace talus
