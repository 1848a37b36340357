#pragma once
// Sedimentation: the placed grains fall and settle before the run proper.
#include <cstdint>
#include <vector>

#include "scenario/build.hpp"

namespace talus {

/// Lets out.world's grains fall and settle under gravity with out.config, behind the temporary
/// walls `gate` (a closed orifice; of material `wall_mat`, their ends joined to the walls' within
/// `joint_distance`) and without drivers, until the kinetic energy falls below
/// packing.settle_energy x sum(m g R) or packing.settle_max_time has passed. The free grains of
/// out.world take their settled positions and angles; out.settled and out.settle_time say how
/// it ended. `progress` (if any) hears the time and kinetic energy every 5 ms of settling.
void sediment(const Scenario& s, const std::vector<SegmentSpec>& gate, std::uint16_t wall_mat,
              double joint_distance, const SettleProgress& progress, BuiltScenario& out);

} // namespace talus
