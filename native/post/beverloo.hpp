#pragma once
// The Beverloo law of silo discharge, W = C (D - k d)^n (Beverloo, Leniger and van de Velde,
// Chem. Eng. Sci. 15, 260, 1961): the rate W through an orifice of width D for grains of
// diameter d, with k the "empty annulus" in diameters. In 2D, dimensional analysis gives
// n = 3/2. Fitted by least squares to measured rates.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace talus {

struct BeverlooFit {
  bool ok = false;
  std::string why_not; ///< when !ok: what the data lack
  bool n_fixed = false;
  /// W = A (D/d - k)^n: A in the rate's unit, k and n dimensionless.
  double A = 0.0, k = 0.0, n = 0.0;
  /// C = A / d^n: W = C (D - k d)^n with D and d in m.
  double C = 0.0;
  /// Standard errors, from the covariance s^2 (J^T J)^-1 with s^2 the residual variance.
  double A_error = 0.0, k_error = 0.0, n_error = 0.0, C_error = 0.0;
  double rms = 0.0; ///< root-mean-square residual, in the rate's unit
  std::size_t points = 0;
};

/// Fits W against D (both per run; several runs may share a D) for grains of mean diameter d,
/// with n free, or fixed at `fixed_n`. Unweighted least squares (Levenberg-Marquardt) in the
/// rate; k is kept below the smallest D/d. Needs more points than parameters, over at least as
/// many distinct widths as parameters.
BeverlooFit fit_beverloo(const std::vector<double>& D, const std::vector<double>& W, double d,
                         std::optional<double> fixed_n = std::nullopt);

/// The fitted rate at width D.
double beverloo_rate(const BeverlooFit& f, double D, double d);

} // namespace talus
