#pragma once
// The warning of a timestep that resolves the stiffest collision in fewer steps than is safe,
// with the advice the native engine follows (talus/timestep_advice.hpp).
#include <cstdio>
#include <string>

#include "talus/timestep_advice.hpp"

namespace talus::lammps {

/// The warning for a shortest collision time `collision` (s) of the pair described by `what`
/// at timestep `dt` (s), or empty where dt resolves it in enough steps.
inline std::string timestep_warning(double collision, double dt, const std::string& what) {
  if (!(collision > 0.0) || !(dt > 0.0) || collision / dt >= min_safe_steps_per_collision)
    return {};
  char text[400];
  std::snprintf(text, sizeof text,
                "the timestep %.3g s resolves the collision of %s (%.3g s, the lightest and "
                "smallest grains present) in %.3g steps; fewer than %.0f are not safe (grains "
                "tunnel or fly off; docs/accuracy.md). The native engine takes t_c / %.0f = "
                "%.3g s",
                dt, what.c_str(), collision, collision / dt, min_safe_steps_per_collision,
                default_timestep_factor, collision / default_timestep_factor);
  return text;
}

} // namespace talus::lammps
