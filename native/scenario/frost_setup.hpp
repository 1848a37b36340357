#pragma once
// The front model's parameters from a scenario's [frost] section and the built grains: the
// automatic values (0 in the file) resolved.
#include "frost/frost_front.hpp"
#include "scenario/scenario.hpp"

namespace talus {

/// stone_radius 0: 1.5 x the median radius of the free grains; column_width 0: the largest
/// stone's diameter; crust_length 0: the column width. The columns span `bounds` in x;
/// thawed_material is looked up in the scenario's materials.
FrostFrontParameters front_parameters(const Scenario& s, const Particles& p, const Rect& bounds);

} // namespace talus
