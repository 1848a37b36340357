#include "drivers/servo.hpp"

#include <algorithm>

namespace talus {

double servo_speed(const Servo& s, const ServoReading& r, double dt) {
  const double error = s.force - r.load;
  const double resistance = r.stiffness * dt + r.damping;
  const double v = resistance > 0.0 ? (s.relaxation * error + r.damping * s.speed) / resistance
                   : error > 0.0    ? s.max_speed
                   : error < 0.0    ? -s.max_speed
                                    : 0.0;
  return std::clamp(v, -s.max_speed, s.max_speed);
}

void servo_advance(Servo& s, const ServoReading& r, double dt) {
  s.speed = servo_speed(s, r, dt);
  s.displacement += s.speed * dt;
}

} // namespace talus
