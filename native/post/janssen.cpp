#include "post/janssen.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "talus/error.hpp"

namespace talus {

double janssen_stress(double saturation, double length, double depth) {
  return saturation * -std::expm1(-depth / length);
}

namespace {

// The free surface of a frame: the mean, over bins two mean diameters wide across the silo, of
// the highest grain top in each.
double free_surface(const Frame& f, double left, double right, double diameter) {
  const auto bins = static_cast<std::size_t>(std::max(1.0, std::floor((right - left) / diameter)));
  std::vector<double> top(bins, -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < f.position.size(); ++i) {
    if (f.kind[i] != 0) continue;
    const double u = (f.position[i].x - left) / (right - left);
    const auto b = std::min(
        bins - 1, static_cast<std::size_t>(std::clamp(u, 0.0, 1.0) * static_cast<double>(bins)));
    top[b] = std::max(top[b], f.position[i].y + f.radius[i]);
  }
  double sum = 0.0;
  std::size_t n = 0;
  for (const double t : top)
    if (std::isfinite(t)) sum += t, ++n;
  return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

// The least-squares S for a given lambda (the model is linear in S) and the residual sum.
std::pair<double, double> best_saturation(const JanssenProfile& p, double length) {
  double gg = 0.0, gs = 0.0;
  for (std::size_t k = 0; k < p.depth.size(); ++k)
    if (p.fitted[k]) {
      const double g = janssen_stress(1.0, length, p.depth[k]);
      gg += g * g, gs += g * p.normal[k];
    }
  const double s = gs / gg;
  double rss = 0.0;
  for (std::size_t k = 0; k < p.depth.size(); ++k)
    if (p.fitted[k]) rss += std::pow(p.normal[k] - janssen_stress(s, length, p.depth[k]), 2);
  return {s, rss};
}

// lambda minimising the residuals: golden sections on log lambda between one bin and a hundred
// times the bed's height (a minimum at that end is a column that does not saturate).
void fit(JanssenProfile& p) {
  std::size_t points = 0;
  for (const bool f : p.fitted) points += f ? 1 : 0;
  if (points < 4) {
    p.why_not = "fewer than 4 bins of wall stress below the surface";
    return;
  }
  const double height = p.surface - p.base;
  double a = std::log(p.bin), b = std::log(100.0 * height);
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 200; ++it) {
    const double c = b - r * (b - a), d = a + r * (b - a);
    if (best_saturation(p, std::exp(c)).second < best_saturation(p, std::exp(d)).second)
      b = d;
    else
      a = c;
  }
  p.length = std::exp(0.5 * (a + b));
  const auto [s, rss] = best_saturation(p, p.length);
  p.saturation = s;
  p.rms = std::sqrt(rss / static_cast<double>(points));
  if (p.length > 50.0 * height) {
    p.why_not = "the wall stress grows linearly over the whole bed: no saturation to fit";
    return;
  }
  // the standard errors from the fit's covariance, s^2 (J^T J)^-1, the bins taken independent
  Eigen::MatrixX2d J(points, 2);
  Eigen::Index row = 0;
  for (std::size_t k = 0; k < p.depth.size(); ++k)
    if (p.fitted[k]) {
      const double e = std::exp(-p.depth[k] / p.length);
      J(row, 0) = 1.0 - e;
      J(row, 1) = -s * e * p.depth[k] / (p.length * p.length);
      ++row;
    }
  const Eigen::Matrix2d covariance =
      (rss / static_cast<double>(points - 2)) * (J.transpose() * J).inverse();
  p.saturation_error = std::sqrt(covariance(0, 0));
  p.length_error = std::sqrt(covariance(1, 1));
  p.measured = true;
}

} // namespace

JanssenProfile janssen_profile(const std::vector<Frame>& frames, const JanssenOptions& o) {
  require(!frames.empty(), "janssen: no snapshots");
  const double width = o.right - o.left;
  double radius = 0.0, mass = 0.0, base = std::numeric_limits<double>::infinity();
  std::size_t grains = 0;
  for (const Frame& f : frames)
    for (std::size_t i = 0; i < f.position.size(); ++i)
      if (f.kind[i] == 0) {
        radius += f.radius[i], ++grains;
        mass += f.mass.empty() ? 0.0 : f.mass[i];
        base = std::min(base, f.position[i].y - f.radius[i]);
      }
  require(grains > 0, "janssen: the snapshots hold no free grains");
  require(mass > 0.0, "janssen: the snapshots do not record the grains' masses (written by an "
                      "older talus); run again");
  radius /= static_cast<double>(grains);
  const auto n_frames = static_cast<double>(frames.size());
  JanssenProfile p;
  p.base = base;
  for (const Frame& f : frames) p.surface += free_surface(f, o.left, o.right, 4.0 * radius);
  p.surface /= n_frames;
  p.bin = o.bin > 0.0 ? o.bin : 16.0 * radius;
  p.weight_density = mass / n_frames * o.gravity / (width * (p.surface - p.base));
  const auto bins = static_cast<std::size_t>(std::ceil((p.surface - p.base) / p.bin));
  p.normal.assign(bins, 0.0), p.shear.assign(bins, 0.0), p.fitted.assign(bins, false);
  // each wall contact of a free grain with a side wall: its point within a tenth of a radius of
  // the wall's line, the wall's push on the grain horizontal (normal) and vertical (friction)
  double normal_sum = 0.0, shear_sum = 0.0;
  bool any = false;
  for (const Frame& f : frames)
    for (const Frame::Chain& c : f.chains) {
      if (!c.has_vector || !c.from_free || c.to_free) continue;
      const bool on_left = std::abs(c.point.x - o.left) < 0.1 * radius;
      if (!on_left && std::abs(c.point.x - o.right) >= 0.1 * radius) continue;
      const double depth = p.surface - c.point.y;
      if (depth < 0.0) continue;
      const auto b = std::min(bins - 1, static_cast<std::size_t>(depth / p.bin));
      const double normal = on_left ? c.force_on_from.x : -c.force_on_from.x;
      p.normal[b] += normal, p.shear[b] += c.force_on_from.y;
      normal_sum += normal, shear_sum += c.force_on_from.y, any = true;
    }
  require(any, "janssen: no grain touches the side walls in the snapshots (are they recorded "
               "with their contacts, and is the silo's width the scenario's?)");
  for (std::size_t b = 0; b < bins; ++b) {
    p.depth.push_back((static_cast<double>(b) + 0.5) * p.bin);
    // per wall: the sum over both walls and every frame, over the bin's height, halved
    p.normal[b] /= 2.0 * n_frames * p.bin, p.shear[b] /= 2.0 * n_frames * p.bin;
    // bins reaching within four mean diameters of the floor feel its corners: left out of the fit
    p.fitted[b] = p.surface - (static_cast<double>(b) + 1.0) * p.bin > p.base + 8.0 * radius;
  }
  p.mobilised_friction = normal_sum > 0.0 ? shear_sum / normal_sum : 0.0;
  fit(p);
  if (p.mobilised_friction > 0.0) {
    p.predicted_saturation = p.weight_density * width / (2.0 * p.mobilised_friction);
    if (p.measured) p.stress_ratio = width / (2.0 * p.mobilised_friction * p.length);
  }
  return p;
}

} // namespace talus
