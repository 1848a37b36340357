#pragma once
// Contacts too soft for the grains' weight: a stiffness that fits a small sphere lets a heavy
// grain (a disk 1 m thick, say) sink far into its neighbours at the speeds the scene reaches,
// and the run stops, later, at the stability guard's overlap limit. Said before the run, with
// the stiffness and the timestep that would fit.
#include <string>

#include "scenario/build.hpp"

namespace talus {

/// The largest overlap, as a share of the radius, of the heaviest free grain meeting a grain
/// like it, or a wall, at simulation.impact_speed (undamped: an upper bound), over the pairs
/// that can meet; with the pair's grain material.
struct SoftContact {
  double fraction = 0.0;
  std::uint16_t material = 0;
  double overlap = 0.0; ///< m
  double mass = 0.0;    ///< kg, of that grain
  bool wall = false;
};
SoftContact softest_contact(const BuiltScenario& b);

/// A warning when that overlap passes a quarter of the radius, naming the material's key, the
/// value that keeps it to a twentieth and the timestep that then follows ("" otherwise).
std::string soft_contact_warning(const Scenario& s, const BuiltScenario& b);

} // namespace talus
