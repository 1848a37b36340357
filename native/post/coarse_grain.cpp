#include "post/coarse_grain.hpp"

#include <cmath>
#include <numbers>

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

Tensor2 outer(Vec2 a, Vec2 b) {
  Tensor2 t;
  t << a.x * b.x, a.x * b.y, a.y * b.x, a.y * b.y;
  return t;
}

// The points of the profile each term reaches: phi is summed over the periodic images.
struct Spreader {
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
  Spreader s{o, {}};
  for (std::size_t k = 0; k < o.points; ++k)
    s.at.push_back(o.lo +
                   (o.hi - o.lo) * static_cast<double>(k) / static_cast<double>(o.points - 1));
  const std::size_t n = o.points;
  FieldProfile out;
  out.at = s.at;
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
      s.spread(along(f.position[i], o.axis), 0.0, [&](std::size_t k, double phi) {
        rho[k] += m * phi, p[k] += (m * phi) * v, mvv[k] += (m * phi) * outer(v, v);
      });
    }
    for (const Frame::Chain& c : f.chains) {
      if (!c.has_vector)
        throw InvalidArgument("the snapshots' contacts lack their force vectors (written by an "
                              "older talus): run the scenario again to coarse-grain it");
      const auto side = [&](Vec2 force, Vec2 centre) {
        const Tensor2 fb = outer(force, centre - c.point);
        s.spread(along(centre, o.axis), along(c.point - centre, o.axis),
                 [&](std::size_t k, double phi) { out.contact[k] += phi * fb; });
      };
      if (c.from_free) side(c.force_on_from, c.from);
      if (c.to_free) side(-1.0 * c.force_on_from, c.to);
    }
    for (std::size_t k = 0; k < n; ++k) {
      out.density[k] += rho[k], out.momentum[k] += p[k];
      const Vec2 v = rho[k] > 0.0 ? (1.0 / rho[k]) * p[k] : Vec2{};
      out.kinetic[k] += mvv[k] - rho[k] * outer(v, v);
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
