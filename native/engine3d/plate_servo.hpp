#pragma once
// A plate held at a target load by a servo (docs/model.md, "Servo walls"): after each step's
// force pass it reads the load the spheres put on it and the stiffness and damping of its
// contacts, and takes the speed for the next step by the 2D servo's rule (drivers/servo.hpp),
// moving along a fixed direction from where it stood at the run's start.
#include <cstdint>
#include <vector>

#include "drivers/servo.hpp"
#include "engine3d/planes.hpp"

namespace talus {

struct PlateServo {
  std::uint32_t plate = 0;        ///< index into the scene's plates
  Vec3 direction{0.0, 0.0, -1.0}; ///< unit: the way the plate moves to press on the spheres
  double force = 0.0;             ///< N: the load wanted, the spheres' push against direction
  double max_speed = 0.0;         ///< m/s: the fastest the plate moves, either way
  double relaxation = 0.5;        ///< the fraction of the error closed per step, in (0, 1]
  double displacement = 0.0;      ///< m along direction from the start (the controller's state)
  double speed = 0.0;             ///< m/s along direction, chosen after the last step
};

/// Throws InvalidArgument naming the servo and what is wrong: a plate that does not exist or
/// that a driver or another servo moves, a direction not of unit length, a speed limit not > 0,
/// a relaxation outside (0, 1].
void validate(const std::vector<PlateServo>& servos, const std::vector<PlateDriver>& drivers,
              std::size_t plates);

/// Puts every servo's plate where its displacement has it, from its start pose, moving at its
/// speed.
void place_servo_plates(std::vector<Plane>& plates, const std::vector<PlateServo>& servos,
                        const std::vector<PlatePose>& start);

/// The servo's speed for the next step from what its plate's contacts say, and its displacement
/// moved by it.
void servo_advance(PlateServo& s, const ServoReading& r, double dt);

} // namespace talus
