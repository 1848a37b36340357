#pragma once
// Flat rigid walls for spheres in 3D and their prescribed motions: where a sphere touches a
// plate, and where a driven plate stands at a time and how fast its points move. The native 3D
// engine and fix granthesis/wall in 3D place and touch their plates by these lines, so that the
// two engines agree to rounding on moving walls too. Standard library only, as every header
// here (LAMMPS' source tree builds them as they are): the turn about an axis is Rodrigues'
// formula on three vectors, not a matrix library's.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "talus/error.hpp"
#include "talus/vector3.hpp"
#include "talus/vibration.hpp"

namespace talus {

inline constexpr double unbounded = std::numeric_limits<double>::infinity();

/// A rectangle of half-widths half_u along axis_u and half_v along normal x axis_u about its
/// centre, or a whole plane (half-widths unbounded). A sphere touches it at the rectangle's point
/// nearest its centre, from either side, on its face or on an edge: a thin rigid plate. It stands
/// still unless a driver moves it (place_plate), which sets its velocity field too.
struct Plane {
  Vec3 centre;
  Vec3 normal{0.0, 0.0, 1.0}; ///< unit
  Vec3 axis_u{1.0, 0.0, 0.0}; ///< unit, perpendicular to the normal
  double half_u = unbounded;  ///< m
  double half_v = unbounded;  ///< m
  std::uint16_t material = 0;
  Vec3 velocity{};         ///< translation, m/s
  Vec3 angular_velocity{}; ///< rotation about `pivot`, rad/s
  Vec3 pivot{};            ///< m
  Vec3 force{};            ///< force the spheres put on the plate in the last step, N

  Vec3 axis_v() const { return cross(normal, axis_u); }
  /// Velocity of the plate's material point at p.
  Vec3 velocity_at(const Vec3& p) const { return velocity + cross(angular_velocity, p - pivot); }
};

/// A plate through `centre` facing `normal` (any length > 0), half-widths as Plane's. Its axis u
/// is the coordinate axis least aligned with the normal, made perpendicular to it (so a plate
/// facing a coordinate axis has coordinate axes for its sides). Throws InvalidArgument for a zero
/// or non-finite normal, or half-widths not > 0.
inline Plane make_plane(Vec3 centre, Vec3 normal, double half_u = unbounded,
                        double half_v = unbounded, std::uint16_t material = 0) {
  const double length = magnitude(normal);
  require(std::isfinite(length) && length > 0.0, "a plane's normal must be finite and not zero");
  Plane p;
  p.centre = centre;
  p.normal = (1.0 / length) * normal;
  const Vec3 n = p.normal;
  const Vec3 seed =
      std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z)
          ? Vec3{1.0, 0.0, 0.0}
          : (std::abs(n.y) <= std::abs(n.z) ? Vec3{0.0, 1.0, 0.0} : Vec3{0.0, 0.0, 1.0});
  const Vec3 u = seed - dot(seed, n) * n;
  p.axis_u = (1.0 / magnitude(u)) * u;
  require(half_u > 0.0 && half_v > 0.0, "a plate's half-widths must be > 0 m");
  p.half_u = half_u;
  p.half_v = half_v;
  p.material = material;
  return p;
}

/// The point of the plate nearest to p.
inline Vec3 closest_point(const Plane& plane, const Vec3& p) {
  const Vec3 q = p - plane.centre;
  const double u = std::clamp(dot(q, plane.axis_u), -plane.half_u, plane.half_u);
  const Vec3 v_axis = plane.axis_v();
  const double v = std::clamp(dot(q, v_axis), -plane.half_v, plane.half_v);
  return plane.centre + u * plane.axis_u + v * v_axis;
}

/// A plate's prescribed motion from where it stands at the motion's start.
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

/// Where a driven plate stands at its motion's start, which its driver moves it from.
struct PlatePose {
  Vec3 centre, normal, axis_u;
};

/// v turned by `angle` (rad) about the unit vector `axis`, counter-clockwise looking down it.
inline Vec3 turned_about(const Vec3& axis, double angle, const Vec3& v) {
  const double c = std::cos(angle), s = std::sin(angle);
  return c * v + s * cross(axis, v) + ((1.0 - c) * dot(axis, v)) * axis;
}

/// Puts plate p where driver d has it t seconds after the motion's start (pose `start`), with
/// the velocity field it has there: the translation, and the rotation about the pivot.
inline void place_plate(Plane& p, const PlateDriver& d, const PlatePose& start, double t) {
  p.centre = start.centre, p.normal = start.normal, p.axis_u = start.axis_u;
  p.velocity = {}, p.angular_velocity = {};
  switch (d.motion) {
  case PlateDriver::Motion::translate:
    p.centre = p.centre + t * d.velocity;
    p.velocity = d.velocity;
    return;
  case PlateDriver::Motion::vibrate: {
    const Vec3 along = (1.0 / magnitude(d.direction)) * d.direction;
    const VibrationState v = vibration_at(d.amplitude, d.frequency, d.phase, t);
    p.centre = p.centre + v.displacement * along;
    p.velocity = v.velocity * along;
    return;
  }
  case PlateDriver::Motion::rotate: {
    const double rate = magnitude(d.angular_velocity);
    if (rate == 0.0) return;
    const Vec3 axis = (1.0 / rate) * d.angular_velocity;
    p.centre = d.pivot + turned_about(axis, rate * t, start.centre - d.pivot);
    p.normal = turned_about(axis, rate * t, start.normal);
    p.axis_u = turned_about(axis, rate * t, start.axis_u);
    p.angular_velocity = d.angular_velocity;
    p.pivot = d.pivot;
    return;
  }
  }
}

} // namespace talus
