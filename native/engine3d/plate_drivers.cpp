#include "engine3d/plate_drivers.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Geometry>

#include "talus/error.hpp"

namespace talus {

namespace {

Vec3 turned(const Eigen::Matrix3d& q, const Vec3& v) {
  const Eigen::Vector3d r = q * Eigen::Vector3d(v.x, v.y, v.z);
  return {r.x(), r.y(), r.z()};
}

} // namespace

void validate(const std::vector<PlateDriver>& drivers, std::size_t plates) {
  std::vector<bool> driven(plates, false);
  for (std::size_t k = 0; k < drivers.size(); ++k) {
    const PlateDriver& d = drivers[k];
    const std::string which = "plate driver " + std::to_string(k);
    require(d.plate < plates, which + ": plate " + std::to_string(d.plate) +
                                  " does not exist; allowed: 0 to " + std::to_string(plates) +
                                  " - 1");
    require(!driven[d.plate], which + ": plate " + std::to_string(d.plate) +
                                  " has a driver already; allowed: one driver a plate");
    driven[d.plate] = true;
    if (d.motion != PlateDriver::Motion::vibrate) continue;
    require(norm(d.direction) > 0.0, which + ": a vibration's direction must not be zero");
    require(d.amplitude >= 0.0 && d.frequency >= 0.0,
            which + ": a vibration's amplitude and frequency must be >= 0 (m, Hz)");
  }
}

void drive_plates(std::vector<Plane>& plates, const std::vector<PlateDriver>& drivers,
                  const std::vector<PlatePose>& start, double t) {
  for (const PlateDriver& d : drivers) {
    Plane& p = plates[d.plate];
    const PlatePose& pose = start[d.plate];
    p.centre = pose.centre, p.normal = pose.normal, p.axis_u = pose.axis_u;
    p.velocity = {}, p.angular_velocity = {};
    switch (d.motion) {
    case PlateDriver::Motion::translate:
      p.centre += t * d.velocity;
      p.velocity = d.velocity;
      break;
    case PlateDriver::Motion::vibrate: {
      const Vec3 along = (1.0 / norm(d.direction)) * d.direction;
      const double w = 2.0 * std::numbers::pi * d.frequency, arg = w * t + d.phase;
      p.centre += (d.amplitude * std::sin(arg)) * along;
      p.velocity = (d.amplitude * w * std::cos(arg)) * along;
      break;
    }
    case PlateDriver::Motion::rotate: {
      const double rate = norm(d.angular_velocity);
      if (rate == 0.0) break;
      const Vec3 axis = (1.0 / rate) * d.angular_velocity;
      const Eigen::Matrix3d q =
          Eigen::AngleAxisd(rate * t, Eigen::Vector3d(axis.x, axis.y, axis.z)).toRotationMatrix();
      p.centre = d.pivot + turned(q, pose.centre - d.pivot);
      p.normal = turned(q, pose.normal);
      p.axis_u = turned(q, pose.axis_u);
      p.angular_velocity = d.angular_velocity;
      p.pivot = d.pivot;
      break;
    }
    }
  }
}

} // namespace talus
