#pragma once
// How finely a timestep must resolve the shortest collision: the native engine's automatic
// timestep and the LAMMPS styles' warning take these one rule.

namespace talus {

/// The automatic timestep's share of the shortest collision time: dt = t_c / factor (the native
/// key simulation.timestep_factor's default; what it costs in restitution: docs/accuracy.md).
inline constexpr double default_timestep_factor = 50.0;

/// Fewer steps per collision than this are not safe: the hard cases of docs/accuracy.md go
/// unstable in LAMMPS' velocity Verlet from about this resolution down, and a dissipative
/// collision's restitution is off by order one before that.
inline constexpr double min_safe_steps_per_collision = 10.0;

} // namespace talus
