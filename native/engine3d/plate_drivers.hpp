#pragma once
// Prescribed motions of a scene's plates, each from where the plate stands at the run's start:
// their checks, and every driven plate placed at a time. One plate's motion is the kernel's
// (talus/plate.hpp: translating, vibrating along a direction, turning about an axis).
#include <cstdint>
#include <string>
#include <vector>

#include "engine3d/planes.hpp"

namespace talus {

/// Throws InvalidArgument naming `which` (a driver, a servo) when `plate` is not one of `plates`.
void require_plate(const std::string& which, std::uint32_t plate, std::size_t plates);

/// Throws InvalidArgument naming the driver and what is wrong (a plate that does not exist or
/// has two drivers, a zero direction, a negative amplitude or frequency).
void validate(const std::vector<PlateDriver>& drivers, std::size_t plates);

/// Puts every driven plate where its driver has it at time t (s), from its start pose, with the
/// velocity field it has there (translation, and rotation about the pivot).
void drive_plates(std::vector<Plane>& plates, const std::vector<PlateDriver>& drivers,
                  const std::vector<PlatePose>& start, double t);

} // namespace talus
