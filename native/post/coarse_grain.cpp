#include "post/coarse_grain.hpp"

#include <cmath>
#include <numbers>

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

// The points of the profile each term reaches: phi is summed over the periodic images.
struct ProfileSpreader {
  const CgOptions& o;
  std::vector<double> at;
  // f(k, weight) at every point k, for phi(y_k - y) (a point) or its mean along [y, y + e]
  template <class F> void spread(double y, double e, F&& f) const {
    const int images = o.period > 0.0 ? 1 : 0;
    for (std::size_t k = 0; k < at.size(); ++k) {
      double sum = 0.0;
      for (int m = -images; m <= images; ++m) {
        const double a = at[k] - y + m * o.period;
        sum += std::abs(e) > 1e-9 * o.width ? (cg_kernel_integral(o.kernel, o.width, a) -
                                               cg_kernel_integral(o.kernel, o.width, a - e)) /
                                                  e
                                            : cg_kernel(o.kernel, o.width, a);
      }
      if (sum != 0.0) f(k, sum / o.across);
    }
  }
};

void check(const CgOptions& o) {
  if (!(o.width > 0.0) || !std::isfinite(o.width))
    throw InvalidArgument("coarse graining: a width of " + std::to_string(o.width) +
                          " m; allowed: > 0 m");
  if (o.points < 2 || !(o.hi > o.lo))
    throw InvalidArgument("coarse graining: a profile needs two points or more over a span > 0");
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

Vec2 FieldProfile::velocity(std::size_t k) const {
  return density[k] > 0.0 ? (1.0 / density[k]) * momentum[k] : Vec2{};
}

FieldProfile coarse_grain(const std::vector<Frame>& frames, const CgOptions& o) {
  check(o);
  ProfileSpreader s{o, {}};
  for (std::size_t k = 0; k < o.points; ++k)
    s.at.push_back(o.lo +
                   (o.hi - o.lo) * static_cast<double>(k) / static_cast<double>(o.points - 1));
  CgSums sums = cg_sums(
      frames, o.points, [&](Vec2 at, auto&& f) { s.spread(along(at, o.axis), 0.0, f); },
      [&](Vec2 centre, Vec2 point, auto&& f) {
        s.spread(along(centre, o.axis), along(point - centre, o.axis), f);
      });
  FieldProfile out;
  out.at = s.at;
  out.density = std::move(sums.density), out.momentum = std::move(sums.momentum);
  out.kinetic = std::move(sums.kinetic), out.contact = std::move(sums.contact);
  out.frames = sums.frames;
  return out;
}

} // namespace talus
