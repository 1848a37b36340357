#pragma once
// The simulation box: where particles may be, and which directions wrap around.
#include "core/vec2.hpp"

namespace talus {

/// An axis-aligned box [lo, hi). Periodic directions wrap; open directions are unbounded for
/// the physics (the box is then only the region the neighbour grid covers initially).
struct Domain {
  Vec2 lo{0.0, 0.0};
  Vec2 hi{1.0, 1.0};
  bool periodic_x = false;
  bool periodic_y = false;

  Vec2 size() const { return hi - lo; }
  bool any_periodic() const { return periodic_x || periodic_y; }

  /// Maps a position into [lo, hi) along each periodic direction.
  Vec2 wrap(Vec2 p) const {
    if (periodic_x) p.x = wrap_coordinate(p.x, lo.x, hi.x);
    if (periodic_y) p.y = wrap_coordinate(p.y, lo.y, hi.y);
    return p;
  }

  /// The unwrapped position of p that has crossed `image` periodic boundaries.
  template <class I> Vec2 unwrapped(Vec2 p, const I& image) const {
    const Vec2 l = size();
    return {p.x + l.x * image.x, p.y + l.y * image.y};
  }

  /// The shortest vector from b to a, taking periodic images into account.
  Vec2 minimum_image(Vec2 a, Vec2 b) const {
    Vec2 d = a - b;
    const Vec2 l = size();
    if (periodic_x) d.x -= l.x * std::nearbyint(d.x / l.x);
    if (periodic_y) d.y -= l.y * std::nearbyint(d.y / l.y);
    return d;
  }

private:
  static double wrap_coordinate(double v, double lo_v, double hi_v) {
    const double l = hi_v - lo_v;
    double w = v - l * std::floor((v - lo_v) / l);
    if (w >= hi_v) w -= l; // guards the rounding case v = hi - tiny
    if (w < lo_v) w = lo_v;
    return w;
  }
};

} // namespace talus
