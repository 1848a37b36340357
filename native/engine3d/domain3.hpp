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
struct Domain3 {
  Vec3 lo{0.0, 0.0, 0.0};
  Vec3 hi{1.0, 1.0, 1.0};
  std::array<bool, 3> periodic{false, false, false};

  Vec3 size() const { return hi - lo; }
  bool any_periodic() const { return periodic[0] || periodic[1] || periodic[2]; }

  /// p mapped into [lo, hi) along each periodic axis; the crossings are added to `image`.
  Vec3 wrap(Vec3 p, Image3& image) const {
    for (int k = 0; k < 3; ++k) {
      if (!periodic[k]) continue;
      const double l = component(hi, k) - component(lo, k);
      double& v = component(p, k);
      double turns = std::floor((v - component(lo, k)) / l);
      v -= turns * l;
      if (v >= component(hi, k)) { // the rounding case v = hi - tiny
        v -= l;
        turns += 1.0;
      }
      if (v < component(lo, k)) v = component(lo, k);
      image[static_cast<std::size_t>(k)] += static_cast<std::int32_t>(turns);
    }
    return p;
  }
  /// The unwrapped position of p that has crossed `image` periodic boundaries.
  Vec3 unwrapped(const Vec3& p, const Image3& image) const {
    const Vec3 l = size();
    return {p.x + l.x * image[0], p.y + l.y * image[1], p.z + l.z * image[2]};
  }
};

} // namespace talus
