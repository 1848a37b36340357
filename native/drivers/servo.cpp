#include "drivers/servo.hpp"

#include <algorithm>

namespace talus {

double servo_speed(double target, double relaxation, double max_speed, double last_speed,
                   const ServoReading& r, double dt) {
  const double error = target - r.load;
  const double resistance = r.stiffness * dt + r.damping;
  const double v = resistance > 0.0 ? (relaxation * error + r.damping * last_speed) / resistance
                   : error > 0.0    ? max_speed
                   : error < 0.0    ? -max_speed
                                    : 0.0;
  return std::clamp(v, -max_speed, max_speed);
}

double servo_speed(const Servo& s, const ServoReading& r, double dt) {
  return servo_speed(s.force, s.relaxation, s.max_speed, s.speed, r, dt);
}

void servo_advance(Servo& s, const ServoReading& r, double dt) {
  s.speed = servo_speed(s, r, dt);
  s.displacement += s.speed * dt;
}

} // namespace talus
