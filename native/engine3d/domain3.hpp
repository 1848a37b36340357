#pragma once
// The box of a scene of spheres: where they may be, and which axes wrap around.
#include <array>
#include <cmath>
#include <cstdint>

#include "core/vec3.hpp"

namespace talus {

/// The periodic boundaries a sphere has crossed, per axis (LAMMPS' image flags).
using Image3 = std::array<std::int32_t, 3>;

/// An axis-aligned box [lo, hi). Periodic axes wrap; along an open axis the box is only the
/// region the neighbour grid covers at first (the physics is unbounded there).
///
/// Lees-Edwards boundaries (docs/model.md, "Lees-Edwards shear"), as in 2D (core/domain.hpp): in
/// a box periodic along x and y, the image across the upper y side sits `shear_offset` further
/// along x and slides at `shear_velocity` along x. A sphere that leaves through the upper side
/// comes in through the lower one moved back by the offset and slowed by that velocity.
struct Domain3 {
  Vec3 lo{0.0, 0.0, 0.0};
  Vec3 hi{1.0, 1.0, 1.0};
  std::array<bool, 3> periodic{false, false, false};
  double shear_offset = 0.0;   ///< m: x of the image above (across y) less that of the box
  double shear_velocity = 0.0; ///< m/s: x velocity of the image above less that of the box

  Vec3 size() const { return hi - lo; }
  bool any_periodic() const { return periodic[0] || periodic[1] || periodic[2]; }
  bool sheared() const { return shear_offset != 0.0 || shear_velocity != 0.0; }

  /// Where the image (sx, sy, sz) of a point is, less the point: the heights across y with the
  /// images' offset along x.
  Vec3 image_shift(int sx, int sy, int sz) const {
    const Vec3 l = size();
    return {sx * l.x + sy * shear_offset, sy * l.y, sz * l.z};
  }

  /// p mapped into [lo, hi) along each periodic axis (across y the image's offset comes off x
  /// first); the widths crossed are added to `image` (not the offset: unwrapped() adds widths),
  /// and `heights` is the number of heights p moved down by (-1: up by one), for the velocity
  /// the image's slide takes off.
  Vec3 wrap(Vec3 p, Image3& image, int* heights = nullptr) const {
    int k_y = 0;
    if (periodic[1]) {
      k_y = wrap_axis(p, 1);
      p.x -= k_y * shear_offset;
    }
    if (heights != nullptr) *heights = k_y;
    image[1] += k_y;
    if (periodic[0]) image[0] += wrap_axis(p, 0);
    if (periodic[2]) image[2] += wrap_axis(p, 2);
    return p;
  }
  /// The unwrapped position of p that has crossed `image` periodic boundaries.
  Vec3 unwrapped(const Vec3& p, const Image3& image) const {
    const Vec3 l = size();
    return {p.x + l.x * image[0], p.y + l.y * image[1], p.z + l.z * image[2]};
  }

private:
  // Maps component k of p into [lo, hi); returns the widths it moved down by.
  int wrap_axis(Vec3& p, int k) const {
    const double l = component(hi, k) - component(lo, k);
    double& v = component(p, k);
    double turns = std::floor((v - component(lo, k)) / l);
    v -= turns * l;
    if (v >= component(hi, k)) { // the rounding case v = hi - tiny
      v -= l;
      turns += 1.0;
    }
    if (v < component(lo, k)) v = component(lo, k);
    return static_cast<int>(turns);
  }
};

} // namespace talus
