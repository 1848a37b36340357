#include "post/coarse_grain.hpp"

#include <cmath>
#include <numbers>

#include <fmt/core.h>

#include "post/coarse_grain_sums.hpp"
#include "talus/error.hpp"

namespace talus {

namespace {

// Lucy's polynomial integrated from 0 to q <= 1: q - 2q^3 + 2q^4 - 3q^5/5 (0.4 at q = 1).
double lucy_half(double q) {
  return q * (1.0 + q * q * (-2.0 + q * (2.0 - 0.6 * q)));
}

// The axis coordinate of v.
double along(Vec2 v, int axis) {
  return axis == 0 ? v.x : v.y;
}

// The points of the profile each term reaches: phi is summed over the periodic images, and
// divided by the extent across.
template <class V> struct ProfileSpreader {
  CgKernel kernel = CgKernel::gaussian;
  double width = 0.0;
  std::vector<double> at;
  double period = 0.0; ///< m, 0: none
  double across = 0.0; ///< m (2D) or m^2 (3D)
  V slide{};           ///< the velocity of the image one period further on beyond its grain's
  bool sliding = false;
  double from = 0.0, to = 0.0,
         scale = 1.0; ///< a place y along the axis is put at to + (y - from) scale

  double put(double y) const { return to + (y - from) * scale; }

  // f(k, weight) at every point k, for phi(y_k - y) (a point) or its mean along [y, y + e]
  template <class F> void spread(double y, double e, F&& f) const {
    const int images = period > 0.0 ? 1 : 0;
    for (std::size_t k = 0; k < at.size(); ++k) {
      double sum = 0.0;
      for (int m = -images; m <= images; ++m) sum += weight(at[k] - y + m * period, e);
      if (sum != 0.0) f(k, sum / across);
    }
  }
  // f(k, weight, dv) for a grain at y, dv the velocity its image there has beyond its own
  template <class F> void spread_point(double y, F&& f) const {
    if (!sliding) return spread(y, 0.0, [&](std::size_t k, double w) { f(k, w, V{}); });
    for (std::size_t k = 0; k < at.size(); ++k)
      for (int m = -1; m <= 1; ++m) { // the image at y - m period
        const double w = weight(at[k] - y + m * period, 0.0);
        if (w != 0.0) f(k, w / across, static_cast<double>(-m) * slide);
      }
  }
  double weight(double a, double e) const {
    return std::abs(e) > 1e-9 * width
               ? (cg_kernel_integral(kernel, width, a) - cg_kernel_integral(kernel, width, a - e)) /
                     e
               : cg_kernel(kernel, width, a);
  }
};

std::vector<double> profile_points(double lo, double hi, std::size_t points) {
  std::vector<double> at;
  for (std::size_t k = 0; k < points; ++k)
    at.push_back(lo + (hi - lo) * static_cast<double>(k) / static_cast<double>(points - 1));
  return at;
}

void check_common(double width, std::size_t points, double lo, double hi) {
  if (!(width > 0.0) || !std::isfinite(width))
    throw InvalidArgument("coarse graining: a width of " + std::to_string(width) +
                          " m; allowed: > 0 m");
  if (points < 2 || !(hi > lo))
    throw InvalidArgument("coarse graining: a profile needs two points or more over a span > 0");
}

void check(const CgOptions& o) {
  check_common(o.width, o.points, o.lo, o.hi);
  if (!(o.across > 0.0)) throw InvalidArgument("coarse graining: the extent across must be > 0 m");
  if (o.axis != 0 && o.axis != 1) throw InvalidArgument("coarse graining: axis 0 (x) or 1 (y)");
}

} // namespace

CgKernel parse_cg_kernel(const std::string& name) {
  if (name == "gaussian") return CgKernel::gaussian;
  if (name == "lucy") return CgKernel::lucy;
  throw InvalidArgument("kernel '" + name + "'; allowed: gaussian, lucy");
}

const char* cg_kernel_name(CgKernel k) {
  return k == CgKernel::gaussian ? "gaussian" : "lucy";
}

double cg_kernel(CgKernel k, double w, double x) {
  if (k == CgKernel::gaussian)
    return std::exp(-0.5 * x * x / (w * w)) / (std::sqrt(2.0 * std::numbers::pi) * w);
  const double q = std::abs(x) / w;
  if (q >= 1.0) return 0.0;
  return 1.25 / w * (1.0 + 3.0 * q) * std::pow(1.0 - q, 3);
}

double cg_kernel_integral(CgKernel k, double w, double x) {
  if (k == CgKernel::gaussian) return 0.5 * std::erfc(-x / (std::numbers::sqrt2 * w));
  const double q = std::min(std::abs(x) / w, 1.0);
  return 0.5 + std::copysign(1.25 * lucy_half(q), x);
}

FieldProfile coarse_grain(const std::vector<Frame>& frames, const CgOptions& o) {
  check(o);
  ProfileSpreader<Vec2> s{o.kernel, o.width, profile_points(o.lo, o.hi, o.points), o.period,
                          o.across};
  CgSums sums = cg_sums(
      frames, o.points, [](const Frame&) {},
      [&](Vec2 at, auto&& f) { s.spread_point(along(at, o.axis), f); },
      [&](Vec2 centre, Vec2 point, auto&& f) {
        s.spread(along(centre, o.axis), along(point - centre, o.axis), f);
      });
  FieldProfile out;
  out.across = o.across;
  out.at = s.at;
  out.density = std::move(sums.density), out.momentum = std::move(sums.momentum);
  out.kinetic = std::move(sums.kinetic), out.contact = std::move(sums.contact);
  out.frames = sums.frames;
  return out;
}

FieldProfile3 coarse_grain(const std::vector<Frame3>& frames, const CgOptions3& o) {
  check_common(o.width, o.points, o.lo, o.hi);
  if (o.axis < 0 || o.axis > 2)
    throw InvalidArgument("coarse graining: axis 0 (x), 1 (y) or 2 (z)");
  const char* const names = "xyz";
  ProfileSpreader<Vec3> s{o.kernel, o.width, profile_points(o.lo, o.hi, o.points)};
  double across_sum = 0.0;
  // each frame's box: the period along the axis, the area across, the slide across y
  const auto begin = [&](const Frame3& f) {
    const Vec3 side = f.box_hi - f.box_lo;
    const auto periodic = [&](int a) {
      return f.periodic[static_cast<std::size_t>(a)] && component(side, a) > 0.0;
    };
    s.across = 1.0;
    for (int b = 0; b < 3; ++b) {
      if (b == o.axis) continue;
      const double given = o.extent[static_cast<std::size_t>(b)];
      const double e = given > 0.0 ? given : (periodic(b) ? component(side, b) : 0.0);
      if (!(e > 0.0))
        throw InvalidArgument(fmt::format("coarse graining: no extent along {} to average over "
                                          "(the snapshot at t = {:g} s is not periodic along it)",
                                          names[b], f.time));
      s.across *= e;
    }
    across_sum += s.across;
    s.period = periodic(o.axis) ? component(side, o.axis) : 0.0;
    s.from = s.to = component(f.box_lo, o.axis), s.scale = 1.0;
    if (s.period > 0.0 && o.period > 0.0)
      s.to = o.lo, s.scale = o.period / s.period, s.period = o.period;
    s.sliding = o.axis == 1 && s.period > 0.0 && f.shear_velocity != 0.0;
    s.slide = Vec3{f.shear_velocity, 0.0, 0.0};
  };
  auto sums = cg_sums(
      frames, o.points, begin,
      [&](const Vec3& at, auto&& f) { s.spread_point(s.put(component(at, o.axis)), f); },
      [&](const Vec3& centre, const Vec3& point, auto&& f) {
        s.spread(s.put(component(centre, o.axis)), s.scale * component(point - centre, o.axis), f);
      });
  FieldProfile3 out;
  out.across = across_sum / static_cast<double>(sums.frames);
  out.at = s.at;
  out.density = std::move(sums.density), out.momentum = std::move(sums.momentum);
  out.kinetic = std::move(sums.kinetic), out.contact = std::move(sums.contact);
  out.frames = sums.frames;
  return out;
}

} // namespace talus
