#pragma once
// Flat walls for spheres: rectangles (or whole planes), rigid, of one material, fixed or
// translating at a constant velocity.
#include <cstdint>
#include <limits>
#include <vector>

#include "core/vec3.hpp"

namespace talus {

inline constexpr double unbounded = std::numeric_limits<double>::infinity();

/// A rectangle of half-widths half_u along axis_u and half_v along normal x axis_u about its
/// centre, or a whole plane (half-widths unbounded). A sphere touches it at the rectangle's point
/// nearest its centre, from either side, on its face or on an edge: a thin rigid plate. It stands
/// still unless a driver moves it (plate_drivers.hpp), which sets its velocity field too.
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

/// A plate through `centre` facing `normal` (any length > 0), its axes chosen from the normal;
/// half-widths as Plane's. Throws InvalidArgument for a zero or non-finite normal.
Plane make_plane(Vec3 centre, Vec3 normal, double half_u = unbounded, double half_v = unbounded,
                 std::uint16_t material = 0);

/// The point of the plate nearest to p.
Vec3 closest_point(const Plane& plane, const Vec3& p);

/// The six faces of the box [lo, hi] as whole planes facing inwards, the top (z = hi.z) left out
/// when `open_top`: a container for pouring.
std::vector<Plane> box_planes(Vec3 lo, Vec3 hi, std::uint16_t material = 0, bool open_top = false);

} // namespace talus
