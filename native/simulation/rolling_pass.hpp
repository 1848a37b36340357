#pragma once
// Rolling resistance (src/talus/rolling_resistance.hpp) in the native engine: a pass after the
// force stage over the touching contacts, which adds each contact's rolling torque to its grains
// and advances its rolling spring. The force stage stays as it is (no law or step shape is
// compiled again for it), and scenes without rolling resistance never run the pass. It runs on
// one thread, in list order, so its sums do not depend on the thread count.
#include <cstdint>

#include "materials/pair_table.hpp"
#include "neighbours/neighbour_list.hpp"
#include "simulation/world.hpp"
#include "talus/law_table.hpp"

namespace talus {

/// Whether a scene has rolling resistance: a material with rolling_friction > 0 (a pair mixes it
/// by the mean, so only then can a pair have some).
bool has_rolling_resistance(const World& world);

/// What the rolling law needs of a contact besides its geometry: the relative spin w_i - w_j
/// (rad/s; a wall's rotation rate for j) and the rolling inertia J_r (kg m^2).
struct RollingKinematics {
  double spin = 0.0;
  double inertia = 0.0;
};
/// For particle i with particle j, or with wall segment `wall` when it is >= 0.
RollingKinematics rolling_kinematics(const World& world, std::uint32_t i, std::uint32_t j,
                                     std::int32_t wall);

/// Adds the rolling torques of every touching contact to the particles' torques and advances
/// the rolling springs (list.rolling, list.wall_rolling, which must be sized); clears the springs
/// of entries that do not touch. `shares`: lever_shares of the lever-arm convention.
void add_rolling_torques(World& world, NeighbourList& list, const PairTable& pairs,
                         NormalLaw normal, double dt, LeverShares shares);

} // namespace talus
