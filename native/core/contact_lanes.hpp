#pragma once
// Two particle-particle contacts computed side by side, one per lane (core/lanes.hpp): the laws,
// the geometry and the force of talus/ instantiated on Lanes, so each lane gives the double
// result to the bit (tests/unit/test_contact_lanes.cpp checks every law pair).
#include "core/lanes.hpp"
#include "talus/contact_force.hpp"
#include "talus/contact_geometry.hpp"
#include "talus/pair_parameters.hpp"

namespace talus {

using PairLanes = PairParametersOf<Lanes>;
using ContactLanes = ContactGeometryOf<Lanes>;
using ForceLanes = ContactForceOf<Lanes>;

/// The parameters of two contacts' material pairs, lane by lane. Inline, so that the fields a law
/// does not read are never loaded.
inline PairLanes pair_lanes(const PairParameters& a, const PairParameters& b) {
  return PairLanes::gather(a, b, [](double x, double y) { return Lanes{x, y}; });
}

} // namespace talus
