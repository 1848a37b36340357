#pragma once
// The simulation box: where particles may be, and which directions wrap around.
#include "core/vec2.hpp"

namespace talus {

/// An axis-aligned box [lo, hi). Periodic directions wrap; open directions are unbounded for
/// the physics (the box is then only the region the neighbour grid covers initially).
///
/// Lees-Edwards boundaries (docs/model.md, "Lees-Edwards"): in a box periodic along x and y, the
/// image across the upper side may sit `shear_offset` further along x and slide at
/// `shear_velocity` along x, the shear rate times the height. A grain that leaves through the
/// upper side comes in through the lower one moved back by the offset and slowed by that
/// velocity. Both 0: plain periodic images.
struct Domain {
  Vec2 lo{0.0, 0.0};
  Vec2 hi{1.0, 1.0};
  bool periodic_x = false;
  bool periodic_y = false;
  double shear_offset = 0.0;   ///< m: x of the image above less that of the box
  double shear_velocity = 0.0; ///< m/s: x velocity of the image above less that of the box

  Vec2 size() const { return hi - lo; }
  bool any_periodic() const { return periodic_x || periodic_y; }

  bool sheared() const { return shear_offset != 0.0 || shear_velocity != 0.0; }

  /// Maps a position into [lo, hi) along each periodic direction; across y the image's offset
  /// comes off x first.
  Vec2 wrap(Vec2 p) const { return wrap(p, nullptr); }

  /// wrap, and the number of heights the position moved down by (-1: up by one), for the
  /// velocity the image's slide takes off (Lees-Edwards).
  Vec2 wrap(Vec2 p, int* heights) const {
    int k = 0;
    if (periodic_y) {
      const double y = wrap_coordinate(p.y, lo.y, hi.y);
      k = static_cast<int>(std::nearbyint((p.y - y) / size().y));
      p.y = y;
      p.x -= k * shear_offset;
    }
    if (periodic_x) p.x = wrap_coordinate(p.x, lo.x, hi.x);
    if (heights != nullptr) *heights = k;
    return p;
  }

  /// Where the image (sx, sy) of a point is, less the point: sx widths and sy heights away, the
  /// heights with the images' offset along x.
  Vec2 image_shift(int sx, int sy) const {
    const Vec2 l = size();
    return {sx * l.x + sy * shear_offset, sy * l.y};
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
    if (periodic_y) {
      const double k = std::nearbyint(d.y / l.y);
      d.y -= l.y * k;
      d.x -= k * shear_offset;
    }
    if (periodic_x) d.x -= l.x * std::nearbyint(d.x / l.x);
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
