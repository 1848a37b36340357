#pragma once
// Integers read back from talus' own text outputs (snapshots, track.csv, contact_events.csv),
// where they are written as numbers: a damaged or edited file can hold anything there, and
// converting a number outside the integer type's range, or one with a fraction, would be
// undefined or wrong.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace talus {

/// v as T, when it is a whole number T holds; otherwise throws std::runtime_error
/// "`where` holds V; allowed: whole numbers LO to HI".
template <class T> T whole_number(double v, const std::string& where) {
  using limits = std::numeric_limits<T>;
  // T's range as doubles, exactly: [lowest, 2^digits) (its largest value may not be one)
  const double lowest = static_cast<double>(limits::lowest());
  const double beyond = std::ldexp(1.0, limits::digits);
  if (!(v >= lowest && v < beyond && v == std::floor(v)))
    throw std::runtime_error(where + " holds " + std::to_string(v) + "; allowed: whole numbers " +
                             std::to_string(limits::lowest()) + " to " +
                             std::to_string(limits::max()));
  return static_cast<T>(v);
}

} // namespace talus
