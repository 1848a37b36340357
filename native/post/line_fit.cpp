#include "post/line_fit.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <fmt/core.h>

namespace talus {

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  LineFit f;
  f.points = x.size();
  if (x.size() != y.size() || x.size() < 2) {
    f.why_not = fmt::format("{} points; a line needs 2 at least", x.size());
    return f;
  }
  if (std::all_of(x.begin(), x.end(), [&](double v) { return v == x.front(); })) {
    f.why_not = "every point has the same x";
    return f;
  }
  const auto n = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixX2d a(n, 2);
  Eigen::VectorXd b(n);
  for (Eigen::Index k = 0; k < n; ++k)
    a(k, 0) = 1.0, a(k, 1) = x[static_cast<std::size_t>(k)], b(k) = y[static_cast<std::size_t>(k)];
  const Eigen::Vector2d c = a.colPivHouseholderQr().solve(b);
  const double rss = (a * c - b).squaredNorm();
  const Eigen::Matrix2d cov =
      (n > 2 ? rss / static_cast<double>(n - 2) : 0.0) * (a.transpose() * a).inverse();
  f.intercept = c(0), f.slope = c(1);
  f.intercept_error = std::sqrt(cov(0, 0)), f.slope_error = std::sqrt(cov(1, 1));
  f.rms = std::sqrt(rss / static_cast<double>(n));
  f.ok = true;
  return f;
}

} // namespace talus
