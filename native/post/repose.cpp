#include "post/repose.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "talus/error.hpp"

namespace talus {

namespace {

// A straight line fitted by least squares to the profile's points of flank `side`.
ReposeFlank fit_flank(const ReposeProfile& p, int side) {
  ReposeFlank out;
  std::vector<std::size_t> picked;
  for (std::size_t k = 0; k < p.x.size(); ++k)
    if (p.flank[k] == side) picked.push_back(k);
  out.points = picked.size();
  if (picked.size() < 3) {
    out.why_not = fmt::format("fewer than 3 bins of its surface lie between {:g} and {:g} of "
                              "the heap's height",
                              surface_band_low, surface_band_high);
    return out;
  }
  const auto n = static_cast<Eigen::Index>(picked.size());
  Eigen::MatrixXd a(n, 2);
  Eigen::VectorXd h(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    a(k, 0) = p.x[picked[static_cast<std::size_t>(k)]];
    a(k, 1) = 1.0;
    h(k) = p.surface[picked[static_cast<std::size_t>(k)]];
  }
  const Eigen::Vector2d line = a.colPivHouseholderQr().solve(h);
  out.measured = true;
  out.slope = line(0);
  out.intercept = line(1);
  out.angle_deg = std::atan(std::abs(out.slope)) * 180.0 / std::numbers::pi;
  out.rms = std::sqrt((a * line - h).squaredNorm() / static_cast<double>(n));
  return out;
}

} // namespace

ReposeProfile repose_profile(const Frame& f) {
  ReposeProfile p;
  double lo = std::numeric_limits<double>::max(), hi = -lo, radii = 0.0;
  std::size_t grains = 0;
  p.base = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < f.position.size(); ++i) {
    if (f.kind[i] != 0) continue;
    lo = std::min(lo, f.position[i].x - f.radius[i]);
    hi = std::max(hi, f.position[i].x + f.radius[i]);
    p.base = std::min(p.base, f.position[i].y - f.radius[i]);
    radii += f.radius[i];
    ++grains;
  }
  if (grains == 0)
    throw InvalidArgument("no free grains in the snapshot at t = " + std::to_string(f.time) +
                          " s: no heap to measure");
  p.bin_width = 4.0 * radii / static_cast<double>(grains);
  const auto bins = static_cast<std::size_t>(std::ceil((hi - lo) / p.bin_width));
  std::vector<double> top(std::max<std::size_t>(bins, 1), -std::numeric_limits<double>::max());
  for (std::size_t i = 0; i < f.position.size(); ++i) {
    if (f.kind[i] != 0) continue;
    const auto b =
        std::min(top.size() - 1, static_cast<std::size_t>((f.position[i].x - lo) / p.bin_width));
    top[b] = std::max(top[b], f.position[i].y + f.radius[i]);
  }
  for (std::size_t b = 0; b < top.size(); ++b) {
    if (top[b] == -std::numeric_limits<double>::max()) continue;
    p.x.push_back(lo + (static_cast<double>(b) + 0.5) * p.bin_width);
    p.surface.push_back(top[b]);
  }
  const auto peak = static_cast<std::size_t>(std::max_element(p.surface.begin(), p.surface.end()) -
                                             p.surface.begin());
  p.height = p.surface[peak] - p.base;
  p.peak_x = p.x[peak];
  p.flank.assign(p.x.size(), 0);
  for (std::size_t k = 0; k < p.x.size(); ++k) {
    const double above = p.surface[k] - p.base;
    if (above >= surface_band_low * p.height && above <= surface_band_high * p.height)
      p.flank[k] = k < peak ? -1 : (k > peak ? 1 : 0);
  }
  p.left = fit_flank(p, -1);
  p.right = fit_flank(p, 1);
  if (p.left.measured && p.right.measured)
    p.angle_deg = 0.5 * (p.left.angle_deg + p.right.angle_deg);
  else if (p.left.measured || p.right.measured)
    p.angle_deg = p.left.measured ? p.left.angle_deg : p.right.angle_deg;
  else
    p.angle_deg = std::numeric_limits<double>::quiet_NaN();
  return p;
}

} // namespace talus
