#pragma once
// How a LAMMPS case written by talus export lammps spells its numbers, in 2D and 3D.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <fmt/format.h>

namespace talus {

/// The shortest text that reads back as x: LAMMPS reads back the same double.
inline std::string exact(double x) {
  return fmt::format("{}", x);
}

/// The steps of an interval (s) at timestep dt, at least one.
inline std::uint64_t steps_of(double interval, double dt) {
  return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(interval / dt)));
}

} // namespace talus
