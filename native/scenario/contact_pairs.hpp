#pragma once
// What the contact laws derive for each pair of materials that can meet (the dampers from the
// restitution), in words: recorded with a run's resolved scenario, so that the damping actually
// used can be read, not only the keys it came from.
#include <string>

#include "simulation/simulation.hpp"

namespace talus {

/// TOML comment lines, one per pair of materials that can meet in w: its restitution and the
/// normal damping the law uses (for a derived Hertz damping, its value for grains of the mean
/// size). Comments, so that the file still reruns the same run: the values are derived again.
std::string describe_contact_pairs(const World& w, const PairTable& pairs,
                                   const SimulationConfig& c);

} // namespace talus
