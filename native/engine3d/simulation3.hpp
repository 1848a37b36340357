#pragma once
// The 3D engine's facade: owns a scene of spheres and runs its steps with velocity Verlet.
//
// What it has: spheres (free or fixed), plates (fixed or driven: translating, vibrating,
// turning, or held at a load), gravity, periodic axes, a deforming periodic cell with Lees-Edwards
// shear (cell3.hpp, Scene3::cell), every law pair of the table and rolling resistance, the
// Verlet list with its springs, velocity Verlet and Gear, the stability guard. What it does not
// have yet is refused where it is set (Spheres::add): moved spheres. Its results are
// bit-identical for any thread count.
#include <cstdint>
#include <string>

#include "engine3d/force_pass3.hpp"
#include "engine3d/gear3.hpp"
#include "engine3d/scene3.hpp"
#include "engine3d/sphere_list.hpp"
#include "materials/pair_table.hpp"

namespace talus {

/// The energies of a scene of spheres (J). Gravity's potential is -m g.r, 0 at the origin.
struct Energies3 {
  double kinetic = 0.0;    ///< 1/2 m v^2, free spheres
  double rotational = 0.0; ///< 1/2 I w^2, free spheres
  double potential = 0.0;  ///< gravity's
  double elastic = 0.0;    ///< stored in the contacts
  double total() const { return kinetic + rotational + potential + elastic; }
};

/// Whether anything in the scene can turn a sphere: a tangential law with friction, rolling
/// resistance, or a free sphere spinning already. A frictionless scene of spheres at rest in spin
/// keeps them so (its contacts exert no torque), and its step leaves spins and torques out.
bool turns_spheres(const Scene3& scene, const Settings3& settings);

/// Everything that determines how a run continues: what a checkpoint saves.
struct SimulationState3 {
  Scene3 scene;
  SphereList list;
  std::vector<PlatePose> start; ///< each plate where it stood at the start, for its driver
  ContactPass3 last;            ///< the last force pass' count and deepest overlap
  GearState3 gear;              ///< Gear's derivatives (empty for velocity Verlet)
  double time = 0.0;
  std::uint64_t steps = 0;
};

class Simulation3 {
public:
  /// Validates the scene and the settings (InvalidArgument naming what is wrong), builds the
  /// list and computes the first forces.
  Simulation3(Scene3 scene, Settings3 settings);
  /// Continues from a saved state exactly: forces, springs and the list with its build positions
  /// are taken as saved, so the continuation is bit-identical to the run that was saved.
  /// `settings.threads` may differ.
  static Simulation3 restore(SimulationState3 state, Settings3 settings);
  /// A copy of the state, for a checkpoint.
  SimulationState3 state() const { return {scene_, list_, start_, last_, gear_, time_, steps_}; }

  /// One step: half kick and drift (Gear: the prediction), plates move, the list is rebuilt if
  /// stale, contact forces, second half kick (Gear: the correction), guard (InstabilityError: a
  /// non-finite velocity, or an overlap beyond the allowed fraction of a radius).
  void step();
  void run(std::uint64_t steps);

  double time() const { return time_; }
  std::uint64_t step_count() const { return steps_; }
  const Scene3& scene() const { return scene_; }
  const Settings3& settings() const { return settings_; }
  const SphereList& list() const { return list_; }
  /// Every material pair's contact parameters.
  const PairTable& table() const { return table_; }
  /// The touching contacts of the last force pass.
  std::size_t contact_count() const { return last_.contacts; }
  /// The last force pass' contacts (of them, those on plates) and deepest overlap.
  const ContactPass3& last_pass() const { return last_; }
  /// The mean number of contacts of a free sphere in the last force pass (plates counted; a
  /// fixed sphere's contacts count for its free partner only).
  double coordination() const;
  /// The threads it runs on: those asked (all cores for 0), but at most one per 500 spheres.
  int threads() const { return threads_; }
  /// What the step specialised to the scene leaves out, for run.json and a run's opening lines:
  /// "frictionless" (no spring per list entry, none cleared or carried over), "history-free" (the
  /// same for a law with friction but no history), "no rotation" (turns_spheres false), "one
  /// material" (the pair parameters put in lanes once), those that apply, or "general".
  std::string step_description() const;
  /// true: the general step, whatever the scene (for the tests that compare the two; the
  /// results are the same to the bit).
  void use_general_step(bool general);
  Energies3 energies() const;
  /// Bytes the engine holds for the run: the spheres' fields, the list with its springs, the
  /// force pass' buffers and Gear's derivatives (capacities, not sizes).
  std::size_t footprint_bytes() const;

private:
  Simulation3(SimulationState3 state, Settings3 settings, bool restored);
  void set_up();
  void compute_forces();
  void forces_after_the_move(); ///< the plates to the step's end, the list if stale, the forces
  void drive_servos();          ///< each servo's speed and displacement for the next step
  void drive_cell();            ///< a cell's rate for the next step, held at a pressure
  void rebuild_list();          ///< the Lees-Edwards offset brought back, then the list built
  void gear_step();
  void fit_springs();  ///< springs per entry where the law or the general step keeps them
  void sort_spheres(); ///< renumbers the spheres in the order of their cells (renumber3.hpp)
  void guard() const;

  Scene3 scene_;
  Settings3 settings_;
  PairTable table_;
  SphereList list_;
  std::vector<PlatePose> start_; ///< each plate where it stood at the start, for its driver
  ForcePass3 force_pass_;
  ContactPass3 last_;
  GearState3 gear_;
  std::vector<ServoReading> servo_reading_; ///< drive_servos' buffers: each servo's reading
  std::vector<std::int32_t> servo_owner_;   ///< and each plate's servo (-1: none)
  int threads_ = 1;
  bool rotation_ = true; ///< false: the step leaves the torques and spins out (turns_spheres)
  bool general_ = false;
  double lag_ = 1.0;
  double time_ = 0.0;
  std::uint64_t steps_ = 0;
};

} // namespace talus
