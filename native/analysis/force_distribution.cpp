#include "analysis/force_distribution.hpp"

#include <algorithm>
#include <cmath>

namespace talus {

namespace {
// Weighted least squares y = a + b x; returns b and its standard error.
std::pair<double, double> fit_line(const std::vector<double>& x, const std::vector<double>& y,
                                   const std::vector<double>& w) {
  double sw = 0, sx = 0, sy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) sw += w[k], sx += w[k] * x[k], sy += w[k] * y[k];
  const double mx = sx / sw, my = sy / sw;
  double sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < x.size(); ++k)
    sxx += w[k] * (x[k] - mx) * (x[k] - mx), sxy += w[k] * (x[k] - mx) * (y[k] - my);
  if (sxx <= 0) return {0.0, 0.0};
  return {sxy / sxx, std::sqrt(1.0 / sxx)};
}
} // namespace

ForceDistribution force_distribution(const std::vector<double>& f, double bin_width) {
  ForceDistribution d;
  d.bin_width = bin_width;
  d.contacts = f.size();
  if (f.empty()) return d;
  const double f_max = *std::max_element(f.begin(), f.end());
  const auto bins = static_cast<std::size_t>(std::ceil(f_max / bin_width)) + 1;
  d.count.assign(bins, 0);
  std::size_t below = 0;
  for (const double v : f) {
    ++d.count[std::min(bins - 1, static_cast<std::size_t>(v / bin_width))];
    below += v < 1.0;
  }
  d.fraction_below_mean = static_cast<double>(below) / static_cast<double>(f.size());
  for (std::size_t k = 0; k < bins; ++k) {
    d.centre.push_back((static_cast<double>(k) + 0.5) * bin_width);
    d.density.push_back(static_cast<double>(d.count[k]) /
                        (static_cast<double>(f.size()) * bin_width));
  }
  std::vector<double> x, y, w, lx, ly, lw;
  for (std::size_t k = 0; k < bins; ++k) {
    if (d.count[k] < 5) continue;
    if (d.centre[k] >= d.fit_from) {
      x.push_back(d.centre[k]);
      y.push_back(std::log(d.density[k]));
      w.push_back(static_cast<double>(d.count[k]));
      d.fit_to = std::max(d.fit_to, d.centre[k]);
    } else if (d.centre[k] >= 0.1) {
      lx.push_back(std::log(d.centre[k]));
      ly.push_back(std::log(d.density[k]));
      lw.push_back(static_cast<double>(d.count[k]));
    }
  }
  d.fit_bins = x.size();
  if (x.size() >= 3) {
    const auto [slope, error] = fit_line(x, y, w);
    d.beta = -slope;
    d.beta_error = error;
  }
  if (lx.size() >= 3) d.alpha = fit_line(lx, ly, lw).first;
  return d;
}

} // namespace talus
