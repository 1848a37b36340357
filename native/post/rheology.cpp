#include "post/rheology.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Dense>
#include <fmt/core.h>

#include "post/block_mean.hpp"

namespace talus {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

struct Walls {
  double base = 0.0, plate = 0.0; // the grain surfaces facing the layer, means over the frames
  bool found = true;
};

// The wall grains below the free grains' mean height are the base, those above the plate.
Walls walls_of(const std::vector<Frame>& frames) {
  Walls w;
  for (const Frame& f : frames) {
    double mid = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < f.position.size(); ++i)
      if (f.kind[i] == 0) mid += f.position[i].y, ++n;
    mid /= static_cast<double>(std::max<std::size_t>(n, 1));
    double base = -inf, plate = inf;
    for (std::size_t i = 0; i < f.position.size(); ++i) {
      if (f.kind[i] == 0) continue;
      const double y = f.position[i].y;
      if (y < mid)
        base = std::max(base, y + f.radius[i]);
      else
        plate = std::min(plate, y - f.radius[i]);
    }
    if (!std::isfinite(base) || !std::isfinite(plate)) w.found = false;
    w.base += base / static_cast<double>(frames.size());
    w.plate += plate / static_cast<double>(frames.size());
  }
  return w;
}

struct BlockValues {
  double shear_rate, pressure, shear_stress, packing, friction, inertial;
};

BlockValues block_values(const std::vector<Frame>& frames, const CgOptions& cg, double diameter,
                         double grain_density) {
  const FieldProfile p = coarse_grain(frames, cg);
  std::vector<double> vx(p.at.size());
  BlockValues b{};
  for (std::size_t k = 0; k < p.at.size(); ++k) {
    vx[k] = p.velocity(k).x;
    const Tensor2 s = p.contact[k] + p.kinetic[k];
    b.pressure += s(1, 1);
    b.shear_stress += 0.5 * (s(0, 1) + s(1, 0));
    b.packing += p.density[k] / grain_density;
  }
  const auto n = static_cast<double>(p.at.size());
  b.pressure /= n, b.shear_stress = std::abs(b.shear_stress / n), b.packing /= n;
  b.shear_rate = std::abs(fit_line(p.at, vx).slope);
  b.friction = b.shear_stress / b.pressure;
  b.inertial = b.shear_rate * diameter / std::sqrt(b.pressure / grain_density);
  return b;
}

} // namespace

GrainScale grain_scale(const Frame& f) {
  GrainScale g;
  double area = 0.0, mass = 0.0, diameter = 0.0;
  for (std::size_t i = 0; i < f.position.size(); ++i)
    if (f.kind[i] == 0) {
      // a snapshot without masses (one from before they were written, or made elsewhere)
      // counts none here; the coarse graining then refuses it by name
      area += std::numbers::pi * f.radius[i] * f.radius[i];
      mass += f.mass.size() == f.position.size() ? f.mass[i] : 0.0;
      diameter += 2.0 * f.radius[i], ++g.grains;
    }
  if (g.grains > 0) g.diameter = diameter / static_cast<double>(g.grains), g.density = mass / area;
  return g;
}

GrainScale grain_scale(const Frame3& f) {
  GrainScale g;
  double volume = 0.0, mass = 0.0, diameter = 0.0;
  for (std::size_t i = 0; i < f.position.size(); ++i)
    if (f.kind[i] == 0) {
      volume += 4.0 / 3.0 * std::numbers::pi * f.radius[i] * f.radius[i] * f.radius[i];
      mass += f.mass.size() == f.position.size() ? f.mass[i] : 0.0;
      diameter += 2.0 * f.radius[i], ++g.grains;
    }
  if (g.grains > 0)
    g.diameter = diameter / static_cast<double>(g.grains), g.density = mass / volume;
  return g;
}

RheologyPoint rheology_point(const std::vector<Frame>& frames, const RheologyOptions& o) {
  RheologyPoint r;
  r.frames = frames.size();
  if (frames.size() < std::max<std::size_t>(o.blocks, 2)) {
    r.why_not = fmt::format("{} snapshots; at least {} are needed (one per block)", frames.size(),
                            std::max<std::size_t>(o.blocks, 2));
    return r;
  }
  const GrainScale scale = grain_scale(frames.front());
  if (scale.grains == 0) {
    r.why_not = "the snapshots hold no free grains";
    return r;
  }
  r.diameter = scale.diameter;
  r.grain_density = scale.density;
  const Walls w = walls_of(frames);
  if (!w.found) {
    r.why_not = "no wall grains both below and above the free grains (a shear cell has a rough "
                "base and a rough plate)";
    return r;
  }
  r.base = w.base, r.plate = w.plate;
  const double gap = w.plate - w.base;
  if (!(gap >= 8.0 * r.diameter)) {
    r.why_not = fmt::format("the gap between the walls is {:.3g} grain diameters; at least 8 are "
                            "needed for a bulk away from them",
                            gap / r.diameter);
    return r;
  }
  r.bulk_lo = w.base + 0.5 * (1.0 - o.bulk_fraction) * gap;
  r.bulk_hi = w.plate - 0.5 * (1.0 - o.bulk_fraction) * gap;
  CgOptions cg;
  cg.kernel = o.kernel, cg.width = o.width, cg.axis = 1;
  cg.lo = r.bulk_lo, cg.hi = r.bulk_hi, cg.points = 41, cg.across = o.across;
  std::vector<BlockValues> blocks;
  const std::size_t per = frames.size() / o.blocks;
  for (std::size_t b = 0; b < o.blocks; ++b) {
    const auto first = frames.begin() + static_cast<std::ptrdiff_t>(b * per);
    const auto last = b + 1 == o.blocks ? frames.end() : first + static_cast<std::ptrdiff_t>(per);
    blocks.push_back(block_values({first, last}, cg, r.diameter, r.grain_density));
  }
  std::tie(r.shear_rate, r.shear_rate_error) = block_mean_error(blocks, &BlockValues::shear_rate);
  std::tie(r.pressure, r.pressure_error) = block_mean_error(blocks, &BlockValues::pressure);
  std::tie(r.shear_stress, r.shear_stress_error) =
      block_mean_error(blocks, &BlockValues::shear_stress);
  std::tie(r.friction, r.friction_error) = block_mean_error(blocks, &BlockValues::friction);
  std::tie(r.packing, r.packing_error) = block_mean_error(blocks, &BlockValues::packing);
  std::tie(r.inertial, r.inertial_error) = block_mean_error(blocks, &BlockValues::inertial);
  r.measured = true;
  return r;
}

double mu_of_i(double mu_s, double mu_2, double i_0, double inertial) {
  return mu_s + (mu_2 - mu_s) / (i_0 / inertial + 1.0);
}

namespace {

struct Linear {
  double mu_s, mu_2, rss;
};

// For a given I_0 the model is linear in mu_s and mu_2: mu = mu_s (1 - g) + mu_2 g.
Linear solve_at(const std::vector<double>& in, const std::vector<double>& mu, double i_0) {
  const auto n = static_cast<Eigen::Index>(in.size());
  Eigen::MatrixXd a(n, 2);
  Eigen::VectorXd y(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double g = in[static_cast<std::size_t>(k)] / (in[static_cast<std::size_t>(k)] + i_0);
    a(k, 0) = 1.0 - g, a(k, 1) = g, y(k) = mu[static_cast<std::size_t>(k)];
  }
  const Eigen::Vector2d c = a.colPivHouseholderQr().solve(y);
  return {c(0), c(1), (a * c - y).squaredNorm()};
}

} // namespace

MuIFit fit_mu_of_i(const std::vector<double>& in, const std::vector<double>& mu) {
  MuIFit f;
  f.points = in.size();
  if (in.size() != mu.size() || in.size() < 4) {
    f.why_not = fmt::format("{} points; the fit needs 4 at least", in.size());
    return f;
  }
  if (std::any_of(in.begin(), in.end(), [](double x) { return !(x > 0.0); })) {
    f.why_not = "an inertial number that is not > 0";
    return f;
  }
  // I_0 between a hundredth of the least I and a hundred times the greatest, on a log scale: a
  // coarse scan for the basin, then golden sections
  const auto [lo_it, hi_it] = std::minmax_element(in.begin(), in.end());
  double lo = std::log(*lo_it / 100.0), hi = std::log(*hi_it * 100.0);
  constexpr int scan = 200;
  double best = lo, best_rss = inf;
  for (int k = 0; k <= scan; ++k) {
    const double u = lo + (hi - lo) * k / scan;
    const double rss = solve_at(in, mu, std::exp(u)).rss;
    if (rss < best_rss) best_rss = rss, best = u;
  }
  double a = std::max(lo, best - (hi - lo) / scan), b = std::min(hi, best + (hi - lo) / scan);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int k = 0; k < 100; ++k) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (solve_at(in, mu, std::exp(c)).rss < solve_at(in, mu, std::exp(d)).rss)
      b = d;
    else
      a = c;
  }
  f.i_0 = std::exp(0.5 * (a + b));
  const Linear l = solve_at(in, mu, f.i_0);
  f.mu_s = l.mu_s, f.mu_2 = l.mu_2;
  const auto n = static_cast<Eigen::Index>(in.size());
  f.rms = std::sqrt(l.rss / static_cast<double>(n));
  // standard errors: s^2 (J^T J)^-1 with J the model's derivatives at the optimum
  Eigen::MatrixXd jac(n, 3);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double x = in[static_cast<std::size_t>(k)], gk = x / (x + f.i_0);
    jac(k, 0) = 1.0 - gk, jac(k, 1) = gk;
    jac(k, 2) = -(f.mu_2 - f.mu_s) * x / ((x + f.i_0) * (x + f.i_0));
  }
  const double s2 = l.rss / static_cast<double>(n - 3);
  const Eigen::Matrix3d cov = s2 * (jac.transpose() * jac).inverse();
  f.mu_s_error = std::sqrt(cov(0, 0)), f.mu_2_error = std::sqrt(cov(1, 1));
  f.i_0_error = std::sqrt(cov(2, 2));
  f.ok = std::isfinite(f.mu_s) && std::isfinite(f.mu_2) && std::isfinite(f.i_0);
  if (!f.ok) f.why_not = "the least squares did not converge";
  return f;
}

} // namespace talus
