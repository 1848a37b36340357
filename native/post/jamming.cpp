#include "post/jamming.hpp"

#include <cmath>

#include <Eigen/Dense>

namespace talus {

namespace {

// Least squares of y = c0 + c1 x: the coefficients and their standard errors, s^2 (X^T X)^-1.
struct Line {
  double c0 = 0.0, c1 = 0.0, e0 = 0.0, e1 = 0.0;
};
Line fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const auto n = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixX2d X(n, 2);
  Eigen::VectorXd Y(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    X(k, 0) = 1.0, X(k, 1) = x[static_cast<std::size_t>(k)];
    Y(k) = y[static_cast<std::size_t>(k)];
  }
  const Eigen::Vector2d c = X.colPivHouseholderQr().solve(Y);
  const double rss = (Y - X * c).squaredNorm();
  const Eigen::Matrix2d cov =
      (n > 2 ? rss / static_cast<double>(n - 2) : 0.0) * (X.transpose() * X).inverse();
  return {c(0), c(1), std::sqrt(cov(0, 0)), std::sqrt(cov(1, 1))};
}

} // namespace

JammingFit fit_jamming(const std::vector<JammingStep>& steps) {
  JammingFit f;
  std::vector<double> p, phi;
  for (const JammingStep& s : steps)
    if (s.pressure > 0.0) p.push_back(s.pressure), phi.push_back(s.packing);
  if (p.size() < 3) {
    f.why_not = "fewer than 3 steps under pressure";
    return f;
  }
  const Line packing = fit_line(p, phi);
  if (!(packing.c1 > 0.0)) {
    f.why_not = "the packing fraction does not grow with the pressure";
    return f;
  }
  f.phi_j = packing.c0, f.phi_j_error = packing.e0;
  f.bulk = 1.0 / packing.c1, f.bulk_error = packing.e1 / (packing.c1 * packing.c1);
  std::vector<double> root, z;
  for (const JammingStep& s : steps)
    if (s.pressure > 0.0 && s.packing > f.phi_j)
      root.push_back(std::sqrt(s.packing - f.phi_j)), z.push_back(s.coordination);
  if (root.size() < 3) {
    f.why_not = "fewer than 3 steps above phi_J";
    return f;
  }
  const Line coordination = fit_line(root, z);
  f.z_j = coordination.c0, f.z_j_error = coordination.e0;
  f.z_slope = coordination.c1, f.z_slope_error = coordination.e1;
  f.measured = true;
  return f;
}

} // namespace talus
