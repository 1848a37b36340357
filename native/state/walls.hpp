#pragma once
// Line-segment walls: straight, rigid, of one material, fixed or moved by a driver.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec2.hpp"

namespace talus {

struct Segment {
  Vec2 a; ///< first end point, m
  Vec2 b; ///< second end point, m
  std::uint16_t material = 0;
  Vec2 velocity{};             ///< translation velocity of the wall, m/s
  double angular_velocity = 0; ///< rotation rate about `pivot`, rad/s
  Vec2 pivot{};                ///< centre of rotation, m
  Vec2 force{};                ///< force the grains put on the wall in the last step, N

  /// Velocity of the wall's material point at p.
  Vec2 velocity_at(Vec2 p) const { return velocity + cross(angular_velocity, p - pivot); }
};

/// The point of segment [a, b] nearest to p.
inline Vec2 closest_point(const Segment& s, Vec2 p) {
  const Vec2 ab = s.b - s.a;
  const double l2 = norm2(ab);
  double u = l2 > 0.0 ? dot(p - s.a, ab) / l2 : 0.0;
  u = u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
  return s.a + u * ab;
}

using Segments = std::vector<Segment>;

/// Makes segment end points closer than `tolerance` one point (the earliest segment's), so that
/// two segments meeting there share it exactly: a particle touching the joint then touches it
/// once (wall_pass.hpp). A tolerance small against the grains' size leaves the shape as it was:
/// it only joins ends that a script meant to be one (two ends a rounding step apart would
/// otherwise push a grain resting on the joint twice). Returns how many ends moved.
std::size_t join_segment_ends(Segments& walls, double tolerance);

} // namespace talus
