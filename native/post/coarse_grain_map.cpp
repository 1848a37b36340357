#include "post/coarse_grain_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "post/coarse_grain_sums.hpp"
#include "talus/error.hpp"

namespace talus {

namespace {

// Gauss-Legendre on [0, 1], 5 points: exact for polynomials of degree 9.
constexpr std::array<double, 5> gl_at{0.04691007703066800, 0.23076534494715845, 0.5,
                                      0.76923465505284155, 0.95308992296933200};
constexpr std::array<double, 5> gl_weight{0.11846344252809454, 0.23931433524968324,
                                          0.28444444444444444, 0.23931433524968324,
                                          0.11846344252809454};

// Calls f(cell, phi(x) phi(y)) for the cells a point's kernel reaches, over periodic images.
struct MapSpreader {
  const CgMapOptions& o;
  const FieldMap& map;
  double reach;
  template <class F> void spread(Vec2 at, F&& f) const {
    const int ix_images = o.period.x > 0.0 ? 1 : 0, iy_images = o.period.y > 0.0 ? 1 : 0;
    for (int mx = -ix_images; mx <= ix_images; ++mx)
      for (int my = -iy_images; my <= iy_images; ++my)
        one(at + Vec2{mx * o.period.x, my * o.period.y}, f);
  }
  template <class F> void one(Vec2 at, F& f) const {
    const auto range = [&](double c, double lo, double cell, std::size_t n) {
      const double a = std::floor((c - reach - lo) / cell), b = std::ceil((c + reach - lo) / cell);
      return std::pair<std::size_t, std::size_t>{
          static_cast<std::size_t>(std::clamp(a, 0.0, static_cast<double>(n))),
          static_cast<std::size_t>(std::clamp(b, 0.0, static_cast<double>(n)))};
    };
    const auto [x0, x1] = range(at.x, map.lo.x, map.cell_x, map.nx);
    const auto [y0, y1] = range(at.y, map.lo.y, map.cell_y, map.ny);
    for (std::size_t iy = y0; iy < y1; ++iy) {
      const double py = cg_kernel(o.kernel, o.width, map.centre(iy * map.nx).y - at.y);
      if (py == 0.0) continue;
      for (std::size_t ix = x0; ix < x1; ++ix) {
        const std::size_t k = iy * map.nx + ix;
        const double phi = py * cg_kernel(o.kernel, o.width, map.centre(k).x - at.x);
        if (phi != 0.0) f(k, phi);
      }
    }
  }
};

void check(const CgMapOptions& o) {
  if (!(o.width > 0.0) || !std::isfinite(o.width))
    throw InvalidArgument("coarse graining: a width of " + std::to_string(o.width) +
                          " m; allowed: > 0 m");
  if (o.nx < 1 || o.ny < 1 || !(o.hi.x > o.lo.x) || !(o.hi.y > o.lo.y))
    throw InvalidArgument("coarse graining: a map needs cells over an area > 0");
}

} // namespace

Vec2 FieldMap::centre(std::size_t k) const {
  return lo + Vec2{(static_cast<double>(k % nx) + 0.5) * cell_x,
                   (static_cast<double>(k / nx) + 0.5) * cell_y};
}

Vec2 FieldMap::velocity(std::size_t k) const {
  return density[k] > 0.0 ? (1.0 / density[k]) * momentum[k] : Vec2{};
}

FieldMap coarse_grain_map(const std::vector<Frame>& frames, const CgMapOptions& o) {
  check(o);
  FieldMap map;
  map.nx = o.nx, map.ny = o.ny, map.lo = o.lo;
  map.cell_x = (o.hi.x - o.lo.x) / static_cast<double>(o.nx);
  map.cell_y = (o.hi.y - o.lo.y) / static_cast<double>(o.ny);
  const MapSpreader s{o, map, (o.kernel == CgKernel::gaussian ? 5.0 : 1.0) * o.width};
  CgSums sums = cg_sums(
      frames, o.nx * o.ny, [](const Frame&) {},
      [&](Vec2 at, auto&& f) {
        s.spread(at, [&](std::size_t k, double phi) { f(k, phi, Vec2{}); });
      },
      [&](Vec2 centre, Vec2 point, auto&& f) {
        const Vec2 branch = point - centre;
        const double pieces = std::max(1.0, std::ceil(norm(branch) / (0.5 * o.width)));
        for (double piece = 0.0; piece < pieces; piece += 1.0)
          for (std::size_t q = 0; q < gl_at.size(); ++q)
            s.spread(centre + ((piece + gl_at[q]) / pieces) * branch,
                     [&](std::size_t k, double phi) { f(k, gl_weight[q] / pieces * phi); });
      });
  map.density = std::move(sums.density), map.momentum = std::move(sums.momentum);
  map.kinetic = std::move(sums.kinetic), map.contact = std::move(sums.contact);
  map.frames = sums.frames;
  return map;
}

} // namespace talus
