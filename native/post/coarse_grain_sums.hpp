#pragma once
// The part of coarse graining that profiles and maps share: each frame's grains and contact
// sides spread onto the points by a given spreader, the kinetic stress taken about each frame's
// own mean velocity, and the mean over the frames (post/coarse_grain.hpp has the formulas).
#include <cstddef>
#include <vector>

#include "analysis/frame.hpp"
#include "analysis/stress.hpp"
#include "talus/error.hpp"

namespace talus {

inline Tensor2 cg_outer(Vec2 a, Vec2 b) {
  Tensor2 t;
  t << a.x * b.x, a.x * b.y, a.y * b.x, a.y * b.y;
  return t;
}

/// The fields' sums at n points.
struct CgSums {
  std::vector<double> density;
  std::vector<Vec2> momentum;
  std::vector<Tensor2> kinetic, contact;
  std::size_t frames = 0;
};

/// Over `frames`: point(at, f) calls f(k, phi) for the points k a grain at `at` reaches, and
/// side(centre, contact_point, f) the same with phi averaged along the branch.
template <class Point, class Side>
CgSums cg_sums(const std::vector<Frame>& frames, std::size_t n, const Point& point,
               const Side& side) {
  CgSums out;
  out.density.assign(n, 0.0), out.momentum.assign(n, Vec2{});
  out.kinetic.assign(n, Tensor2::Zero()), out.contact.assign(n, Tensor2::Zero());
  for (const Frame& f : frames) {
    if (f.mass.size() != f.position.size())
      throw InvalidArgument("the snapshots lack the grains' masses (written by an older talus): "
                            "run the scenario again to coarse-grain it");
    std::vector<double> rho(n, 0.0);
    std::vector<Vec2> p(n, Vec2{});
    std::vector<Tensor2> mvv(n, Tensor2::Zero());
    for (std::size_t i = 0; i < f.position.size(); ++i) {
      if (f.kind[i] != 0) continue;
      const double m = f.mass[i];
      const Vec2 v = f.velocity[i];
      point(f.position[i], [&](std::size_t k, double phi) {
        rho[k] += m * phi, p[k] += (m * phi) * v, mvv[k] += (m * phi) * cg_outer(v, v);
      });
    }
    for (const Frame::Chain& c : f.chains) {
      if (!c.has_vector)
        throw InvalidArgument("the snapshots' contacts lack their force vectors (written by an "
                              "older talus): run the scenario again to coarse-grain it");
      const auto one = [&](Vec2 force, Vec2 centre) {
        const Tensor2 fb = cg_outer(force, centre - c.point);
        side(centre, c.point, [&](std::size_t k, double phi) { out.contact[k] += phi * fb; });
      };
      if (c.from_free) one(c.force_on_from, c.from);
      if (c.to_free) one(-1.0 * c.force_on_from, c.to);
    }
    for (std::size_t k = 0; k < n; ++k) {
      out.density[k] += rho[k], out.momentum[k] += p[k];
      const Vec2 v = rho[k] > 0.0 ? (1.0 / rho[k]) * p[k] : Vec2{};
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
