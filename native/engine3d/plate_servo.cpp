#include "engine3d/plate_servo.hpp"

#include <cmath>
#include <string>

#include "talus/error.hpp"

namespace talus {

void validate(const std::vector<PlateServo>& servos, const std::vector<PlateDriver>& drivers,
              std::size_t plates) {
  std::vector<bool> moved(plates, false);
  for (const PlateDriver& d : drivers)
    if (d.plate < plates) moved[d.plate] = true;
  for (std::size_t k = 0; k < servos.size(); ++k) {
    const PlateServo& s = servos[k];
    const std::string which = "plate servo " + std::to_string(k);
    require_plate(which, s.plate, plates);
    require(!moved[s.plate], which + ": plate " + std::to_string(s.plate) +
                                 " is moved already; allowed: one driver or servo a plate");
    moved[s.plate] = true;
    require(std::abs(norm(s.direction) - 1.0) < 1e-12,
            which + ": its direction must be a unit vector");
    require(s.max_speed > 0.0 && std::isfinite(s.max_speed),
            which + ": its max_speed must be finite and > 0 m/s");
    require(s.relaxation > 0.0 && s.relaxation <= 1.0,
            which + ": its relaxation must be in (0, 1]");
    require(std::isfinite(s.force), which + ": its force must be finite");
  }
}

void place_servo_plates(std::vector<Plane>& plates, const std::vector<PlateServo>& servos,
                        const std::vector<PlatePose>& start) {
  for (const PlateServo& s : servos) {
    Plane& p = plates[s.plate];
    const PlatePose& from = start[s.plate];
    p.centre = from.centre + s.displacement * s.direction;
    p.normal = from.normal, p.axis_u = from.axis_u;
    p.velocity = s.speed * s.direction;
    p.angular_velocity = {};
  }
}

void servo_advance(PlateServo& s, const ServoReading& r, double dt) {
  s.speed = servo_speed(s.force, s.relaxation, s.max_speed, s.speed, r, dt);
  s.displacement += s.speed * dt;
}

} // namespace talus
