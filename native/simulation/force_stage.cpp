// The force stage, block by block of rows: every sum has an order fixed by the list alone, so the
// result does not depend on the number of threads, and no floating-point atomics are needed.
#include "simulation/force_stage.hpp"

#include <vector>

#include "core/capacity_bytes.hpp"

namespace talus {

// The build makes one translation unit per law pair (force_stage_laws.cpp.in) from these counts.
static_assert(NormalLaws::size == TALUS_NORMAL_LAW_COUNT &&
                  TangentialLaws::size == TALUS_TANGENTIAL_LAW_COUNT,
              "a law was added to or taken from src/talus/law_table.hpp: set the counts of "
              "TALUS_NORMAL_LAW_COUNT and TALUS_TANGENTIAL_LAW_COUNT in native/CMakeLists.txt");

PassReport ForceStage::compute(World& world, NeighbourList& list, const PairTable& pairs,
                               Finish finish, double drift_bound, int threads,
                               const StepFeatures& features) {
  wall_force_.resize(list.wall_segment.size());
  deferred_.resize(list.block_first_slot.back());
  // The candidates stay valid while two grains cannot have closed their gap: each moved at most
  // drift_bound - candidates_base_ (drift_margin kept for rounding). An unknown bound (infinite,
  // or NaN as infinity less infinity) chooses them again at every stage.
  const bool refresh = candidates_stale_ ||
                       !(2.0 * (drift_bound - candidates_base_) <= drift_margin * candidates_.skin);
  if (refresh) {
    candidates_.skin = ContactCandidates::skin_fraction * list.skin;
    candidates_base_ = drift_bound;
    candidates_stale_ = false;
    ++candidate_choices_;
  }
  // each law pair's instantiation is compiled apart (force_stage_laws.hpp)
  return with_contact_law(normal_, tangential_, [&]<class N, class T>() {
    return compute_with<N, T>(world, list, pairs, finish, refresh, threads, features);
  });
}

std::size_t ForceStage::candidate_bytes() const {
  return capacity_bytes(candidates_.entry) + capacity_bytes(candidates_.slot) +
         capacity_bytes(candidates_.count);
}

std::size_t ForceStage::footprint_bytes() const {
  return capacity_bytes(deferred_) + capacity_bytes(wall_force_) + schedule_.footprint_bytes();
}

} // namespace talus
