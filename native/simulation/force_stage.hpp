#pragma once
// Stage 4 of a step: the contact forces of the current state, and what lasts from one force stage
// to the next (the contact candidates, the deferred and wall force slots, the blocks' schedule).
// Its parts, each in a file of its own: the schedule of the blocks (block_schedule.hpp), the
// touch test and the candidates (contact_candidates.hpp), the pair pass (pair_pass.hpp), the
// wall pass (wall_pass.hpp), the late pass (late_pass.hpp) and what is done to a particle once
// its force is complete (particle_finish.hpp). The laws come from src/talus.
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/contact_vectors.hpp"
#include "integrate/integrator.hpp"
#include "materials/pair_table.hpp"
#include "neighbours/neighbour_list.hpp"
#include "simulation/block_schedule.hpp"
#include "simulation/contact_candidates.hpp"
#include "simulation/step_features.hpp"
#include "simulation/world.hpp"
#include "talus/law_table.hpp"

namespace talus {

class PairLaneSource;

/// The share of a drift limit an upper bound of the drift may reach before the shortcuts it
/// allows stop (the neighbour list's drift test, the contact candidates): the rest is for
/// rounding. Each pass's displacement is rounded once more when it is added to a position, half a
/// unit in the last place of the coordinate, which over the hundreds of steps a list lasts stays
/// far below a tenth of the limit.
inline constexpr double drift_margin = 0.9;

class ForceStage {
public:
  /// What the stage does to each particle as soon as its force is complete.
  enum class Finish {
    nothing,
    verlet_correct,         ///< velocity Verlet's second half kick
    verlet_correct_predict, ///< that, then the next step's first half kick and drift
  };
  ForceStage(NormalLaw normal, TangentialLaw tangential, double dt, double verlet_lag = 1.0,
             LeverArm lever_arm = LeverArm::contact_point)
      : normal_(normal), tangential_(tangential), dt_(dt), verlet_lag_(verlet_lag),
        share_(lever_shares(lever_arm)) {}

  /// The forces and torques of every particle (weight and contacts) and the walls' reactions,
  /// then `finish` for every particle. `drift_bound` is an upper bound of how far any free
  /// particle moved since the list's build (m; infinite if unknown): the candidates are chosen
  /// again when two grains could have closed their gap. Returns whether every corrected velocity
  /// is finite and, with verlet_correct_predict, the prediction's largest squared displacement.
  /// The step leaves out what `features` says the scene does not use (step_features.hpp).
  PassReport compute(World& world, NeighbourList& list, const PairTable& pairs, Finish finish,
                     double drift_bound, int threads, const StepFeatures& features);

  /// The list changed (built, renumbered, a grain held or freed): choose the candidates again.
  void list_changed() { candidates_stale_ = true; }
  /// The drift bound was lowered from `from` to `to` (the positions were compared with the
  /// build's). The candidates' base moves by as much, so that the bound's growth since they were
  /// chosen still bounds every grain's move since then; from an unknown bound (infinite) they are
  /// chosen again.
  void drift_bound_lowered(double from, double to) {
    if (std::isfinite(from))
      candidates_base_ -= from - to;
    else
      candidates_stale_ = true;
  }
  /// The pass before the next stage set every force and torque as the stage starts them
  /// (start_forces): the fused passes do, while they have them in cache.
  void forces_started(bool started) { forces_started_ = started; }
  /// The largest overlap / smaller radius of the last stage.
  double deepest_overlap() const { return deepest_overlap_; }
  /// How many stages chose the candidates again.
  std::uint64_t candidate_choices() const { return candidate_choices_; }
  /// Bytes of the contact candidates.
  std::size_t candidate_bytes() const;
  /// Bytes of everything else the stage holds: deferred slots, wall forces, the schedule.
  std::size_t footprint_bytes() const;

  /// compute for the laws N and T (force_stage_laws.hpp): instantiated once per law pair, each
  /// in a translation unit of its own.
  template <class N, class T>
  PassReport compute_with(World& world, NeighbourList& list, const PairTable& pairs, Finish finish,
                          bool refresh, int threads, const StepFeatures& features);

private:
  template <class N, class T, class S, class Done>
  PassReport run(World& world, NeighbourList& list, const PairTable& pairs, bool refresh,
                 const Done& done, int threads, const StepFeatures& features);
  /// Block b's rows: starts their forces (unless started), then each stretch's touch test, pair
  /// pass and `done` for the particles that are complete. Returns the worst overlap ratio.
  /// `Sliding`: Lees-Edwards images move (pair_pass.hpp), a copy of its own so that the step
  /// without them keeps its code as it was.
  template <class N, class T, class S, bool Sliding, class Done>
  double block(BlockArrays& a, const NeighbourList& list, const PairLaneSource& pairs,
               std::ptrdiff_t b, bool refresh, bool started, Vec2 gravity, const Done& done,
               PassReport& report);
  NormalLaw normal_;
  TangentialLaw tangential_;
  double dt_;
  double verlet_lag_; ///< velocity Verlet's convention (integrator.hpp, verlet_lag)
  LeverShares share_; ///< the lever arms' convention (lever_shares, talus/contact_geometry.hpp)
  std::vector<PairForce> deferred_; ///< pair forces waiting for a later block's particle
  std::vector<PairForce> wall_force_;
  ContactCandidates candidates_;
  double candidates_base_ = 0.0; ///< the drift bound when the candidates were chosen
  bool candidates_stale_ = true;
  BlockSchedule schedule_;
  bool forces_started_ = false;
  double deepest_overlap_ = 0.0;
  std::uint64_t candidate_choices_ = 0;
};

} // namespace talus
