#pragma once
// The sinusoidal vibration of a driven wall (the thesis' shaken silo), shared by every engine:
// the native drivers and fix granthesis/wall move a vibrating body by the same arithmetic.
#include <cmath>
#include <numbers>

namespace talus {

/// Where a vibrating body is along its direction, and how fast it moves there.
struct VibrationState {
  double displacement = 0.0; ///< m
  double velocity = 0.0;     ///< m/s
};

/// s(t) = A sin(2 pi f t + phase) and its rate, t seconds after the vibration's start.
inline VibrationState vibration_at(double amplitude, double frequency, double phase, double t) {
  const double w = 2.0 * std::numbers::pi * frequency;
  return {amplitude * std::sin(w * t + phase), amplitude * w * std::cos(w * t + phase)};
}

} // namespace talus
