#pragma once
// The part of coarse graining that profiles and maps, in 2D and in 3D, share: each frame's grains
// and contact sides spread onto the points by a given spreader, the kinetic stress taken about
// each frame's own mean velocity, and the mean over the frames (post/coarse_grain.hpp has the
// formulas).
#include <cstddef>
#include <vector>

#include "analysis/frame.hpp"
#include "analysis/frame3.hpp"
#include "analysis/stress.hpp"
#include "analysis/stress3.hpp"
#include "talus/error.hpp"

namespace talus {

inline Tensor2 cg_outer(Vec2 a, Vec2 b) {
  Tensor2 t;
  t << a.x * b.x, a.x * b.y, a.y * b.x, a.y * b.y;
  return t;
}

inline Tensor3 cg_outer(const Vec3& a, const Vec3& b) {
  Tensor3 t;
  t << a.x * b.x, a.x * b.y, a.x * b.z, a.y * b.x, a.y * b.y, a.y * b.z, a.z * b.x, a.z * b.y,
      a.z * b.z;
  return t;
}

/// The fields' sums at n points, of grains in the plane (V = Vec2) or in space (V = Vec3).
template <class V> struct CgSumsOf {
  using Tensor = decltype(cg_outer(V{}, V{}));
  std::vector<double> density;
  std::vector<V> momentum;
  std::vector<Tensor> kinetic, contact;
  std::size_t frames = 0;
};
using CgSums = CgSumsOf<Vec2>;

/// Over `frames`: begin(frame) first, then point(at, f) calls f(k, phi, dv) for the points k a
/// grain at `at` reaches (dv: the velocity an image of it has beyond its own, Lees-Edwards'), and
/// side(centre, contact_point, f) calls f(k, phi) with phi averaged along the branch.
template <class FrameT, class Begin, class Point, class Side>
auto cg_sums(const std::vector<FrameT>& frames, std::size_t n, const Begin& begin,
             const Point& point, const Side& side) {
  using V = typename decltype(FrameT{}.position)::value_type;
  using Tensor = typename CgSumsOf<V>::Tensor;
  CgSumsOf<V> out;
  out.density.assign(n, 0.0), out.momentum.assign(n, V{});
  out.kinetic.assign(n, Tensor::Zero()), out.contact.assign(n, Tensor::Zero());
  for (const FrameT& f : frames) {
    if (f.mass.size() != f.position.size())
      throw InvalidArgument("the snapshots lack the grains' masses (written by an older talus): "
                            "run the scenario again to coarse-grain it");
    begin(f);
    std::vector<double> rho(n, 0.0);
    std::vector<V> p(n, V{});
    std::vector<Tensor> mvv(n, Tensor::Zero());
    for (std::size_t i = 0; i < f.position.size(); ++i) {
      if (f.kind[i] != 0) continue;
      const double m = f.mass[i];
      point(f.position[i], [&](std::size_t k, double phi, const V& dv) {
        const V v = f.velocity[i] + dv;
        rho[k] += m * phi, p[k] += (m * phi) * v, mvv[k] += (m * phi) * cg_outer(v, v);
      });
    }
    for (const auto& c : f.chains) {
      if (!c.has_vector)
        throw InvalidArgument("the snapshots' contacts lack their force vectors (written by an "
                              "older talus): run the scenario again to coarse-grain it");
      const auto one = [&](const V& force, const V& centre) {
        const Tensor fb = cg_outer(force, centre - c.point);
        side(centre, c.point, [&](std::size_t k, double phi) { out.contact[k] += phi * fb; });
      };
      if (c.from_free) one(c.force_on_from, c.from);
      if (c.to_free) one(-1.0 * c.force_on_from, c.to);
    }
    for (std::size_t k = 0; k < n; ++k) {
      out.density[k] += rho[k], out.momentum[k] += p[k];
      const V v = rho[k] > 0.0 ? (1.0 / rho[k]) * p[k] : V{};
      out.kinetic[k] += mvv[k] - rho[k] * cg_outer(v, v);
    }
    ++out.frames;
  }
  if (out.frames == 0) throw InvalidArgument("coarse graining: no snapshots to average");
  const double per = 1.0 / static_cast<double>(out.frames);
  for (std::size_t k = 0; k < n; ++k) {
    out.density[k] *= per, out.momentum[k] = per * out.momentum[k];
    out.kinetic[k] *= per, out.contact[k] *= per;
  }
  return out;
}

} // namespace talus
