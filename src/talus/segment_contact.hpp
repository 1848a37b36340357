#pragma once
// Where a particle touches a straight wall segment, shared by every engine: the nearest point of
// the segment, whether the particle touches it, and the rule that a particle resting on the
// shared end point of two segments touches that point once.
#include <cstddef>

namespace talus {

/// A particle of radius R at (x, y) against the segment from a to b.
struct SegmentHit {
  double x = 0.0, y = 0.0; ///< the segment's point nearest to the particle's centre (m)
  double u = 0.0;          ///< its position along the segment: 0 at a, 1 at b
  bool touching = false;   ///< closer than R, and not at the centre itself
  bool vertex() const { return u <= 0.0 || u >= 1.0; }
};

inline SegmentHit segment_hit(double ax, double ay, double bx, double by, double x, double y,
                              double radius) {
  SegmentHit h;
  const double abx = bx - ax, aby = by - ay;
  const double l2 = abx * abx + aby * aby;
  h.u = l2 > 0.0 ? ((x - ax) * abx + (y - ay) * aby) / l2 : 0.0;
  if (h.u <= 0.0) {
    h.x = ax, h.y = ay;
  } else if (h.u >= 1.0) {
    h.x = bx, h.y = by;
  } else {
    h.x = ax + h.u * abx, h.y = ay + h.u * aby;
  }
  const double dx = x - h.x, dy = y - h.y;
  const double d2 = dx * dx + dy * dy;
  h.touching = d2 < radius * radius && d2 > 0.0;
  return h;
}

/// Whether hit k (at an end point of its segment) repeats a contact the particle has already:
/// it is dropped when a segment that shares that end point is touched along its face, or when
/// an earlier hit touches the same end point. `hits` are the particle's hits on its `count`
/// segments, in order; `shares(m, x, y)` says whether hit m's segment has (x, y) as an end point.
template <class Hits, class Shares>
bool duplicate_vertex(const Hits& hits, std::size_t count, std::size_t k, Shares&& shares) {
  const double vx = hits[k].x, vy = hits[k].y;
  for (std::size_t m = 0; m < count; ++m) {
    if (m == k || !hits[m].touching) continue;
    if (!shares(m, vx, vy)) continue;
    if (!hits[m].vertex() || m < k) return true;
  }
  return false;
}

} // namespace talus
