#pragma once
// The thesis' uniform freeze (sec. 5.2): once the grains have come to rest, every free grain is
// lifted by the heave factor above the floor at once (src/talus/frost_heave.hpp). The run layer
// decides when (run/frost_events.hpp); this is what a freeze does and what "at rest" means.
#include "simulation/simulation.hpp"

namespace talus {

/// The energy the kinetic threshold is a fraction of: the sum of m g R over the free grains
/// (a frost model may hold some), J.
double rest_energy_scale(const Simulation& sim);

/// Heaves every free grain: its height above `floor` (m) times `factor`.
void freeze_uniformly(Simulation& sim, double floor, double factor);

} // namespace talus
