#pragma once
// Least squares of a straight line y = intercept + slope x, with the coefficients' standard
// errors from the covariance s^2 (X^T X)^-1 (Eigen), for the analyses' linear laws.
#include <cstddef>
#include <string>
#include <vector>

namespace talus {

struct LineFit {
  bool ok = false;
  std::string why_not;
  double intercept = 0.0, intercept_error = 0.0;
  double slope = 0.0, slope_error = 0.0;
  double rms = 0.0; ///< the points' scatter about the line
  std::size_t points = 0;
};

/// Needs 2 points with different x (the errors are 0 with 2: no scatter to estimate them from).
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

} // namespace talus
