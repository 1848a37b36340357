#pragma once
// Prescribed motions of plates: translating, vibrating along a direction, turning about an
// axis, each from where the plate stands at the run's start.
#include <cstdint>
#include <vector>

#include "engine3d/planes.hpp"

namespace talus {

struct PlateDriver {
  enum class Motion : std::uint8_t { translate, vibrate, rotate };
  std::uint32_t plate = 0; ///< index into the scene's plates
  Motion motion = Motion::translate;
  Vec3 velocity{};               ///< translate: m/s
  Vec3 direction{0.0, 0.0, 1.0}; ///< vibrate: along it (any length > 0)
  double amplitude = 0.0;        ///< vibrate: m
  double frequency = 0.0;        ///< vibrate: Hz
  double phase = 0.0;            ///< vibrate: rad; the offset is A sin(2 pi f t + phase)
  Vec3 pivot{};                  ///< rotate: a point of the axis, m
  Vec3 angular_velocity{};       ///< rotate: rad/s, along the axis
};

/// Where a driven plate stands at the run's start, which its driver moves it from.
struct PlatePose {
  Vec3 centre, normal, axis_u;
};

/// Throws InvalidArgument naming the driver and what is wrong (a plate that does not exist or
/// has two drivers, a zero direction, a negative amplitude or frequency).
void validate(const std::vector<PlateDriver>& drivers, std::size_t plates);

/// Puts every driven plate where its driver has it at time t (s), from its start pose, with the
/// velocity field it has there (translation, and rotation about the pivot).
void drive_plates(std::vector<Plane>& plates, const std::vector<PlateDriver>& drivers,
                  const std::vector<PlatePose>& start, double t);

} // namespace talus
