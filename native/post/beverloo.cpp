#include "post/beverloo.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <Eigen/Dense>
#include <fmt/core.h>

namespace talus {

namespace {

using Params = Eigen::Vector3d; // (A, k, n)

// The model's parameters in the order (A, k, n); p = 2 leaves n out.
struct Model {
  const std::vector<double>& x; // D/d
  const std::vector<double>& W;
  double n_fixed;
  Eigen::Index p;

  double n(const Params& q) const { return p == 3 ? q[2] : n_fixed; }
  double rss(const Params& q) const {
    double s = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double e = W[i] - q[0] * std::pow(x[i] - q[1], n(q));
      s += e * e;
    }
    return s;
  }
  // J^T J and J^T e over the p free parameters at q, e the residuals
  void normal(const Params& q, Eigen::MatrixXd& jtj, Eigen::VectorXd& jte) const {
    jtj = Eigen::MatrixXd::Zero(p, p), jte = Eigen::VectorXd::Zero(p);
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double u = x[i] - q[1], un = std::pow(u, n(q));
      const Params j{un, -q[0] * n(q) * un / u, q[0] * un * std::log(u)};
      const double e = W[i] - q[0] * un;
      jte += j.head(p) * e;
      jtj += j.head(p) * j.head(p).transpose();
    }
  }
};

} // namespace

BeverlooFit fit_beverloo(const std::vector<double>& D, const std::vector<double>& W, double d,
                         std::optional<double> fixed_n) {
  BeverlooFit f;
  f.n_fixed = fixed_n.has_value();
  f.points = std::min(D.size(), W.size());
  const Eigen::Index p = fixed_n ? 2 : 3;
  std::vector<double> x;
  for (std::size_t i = 0; i < f.points; ++i) x.push_back(D[i] / d);
  const std::set<double> widths(x.begin(), x.end());
  const auto unknowns = static_cast<std::size_t>(p);
  if (!(d > 0.0) || f.points <= unknowns || widths.size() < unknowns) {
    f.why_not = fmt::format("a fit with {} free parameters needs more than {} runs over at least "
                            "{} orifice widths (got {} runs, {} widths)",
                            p, p, p, f.points, widths.size());
    return f;
  }
  const Model m{x, W, fixed_n.value_or(1.5), p};
  const double x_min = *widths.begin();
  Params q{0.0, std::min(1.5, 0.5 * x_min), m.n_fixed};
  { // A from the linear least squares at the starting k and n
    double su = 0.0, sw = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double u = std::pow(x[i] - q[1], q[2]);
      su += u * u, sw += u * W[i];
    }
    q[0] = sw / su;
  }
  double lambda = 1e-3, rss = m.rss(q);
  Eigen::MatrixXd jtj;
  Eigen::VectorXd jte;
  for (int it = 0; it < 500; ++it) {
    m.normal(q, jtj, jte);
    Eigen::MatrixXd damped = jtj;
    damped.diagonal() *= 1.0 + lambda;
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(damped);
    if (!lu.isInvertible()) break;
    Params next = q;
    next.head(p) += lu.solve(jte);
    const double r = next[1] < x_min ? m.rss(next) : INFINITY;
    if (std::isfinite(r) && r <= rss) {
      const bool small = rss - r <= 1e-14 * rss;
      q = next, rss = r, lambda = std::max(lambda / 3.0, 1e-12);
      if (small) break;
    } else {
      lambda *= 4.0;
      if (lambda > 1e12) break;
    }
  }
  m.normal(q, jtj, jte);
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(jtj);
  if (!lu.isInvertible()) {
    f.why_not = "the fit is degenerate (the rates do not determine the parameters)";
    return f;
  }
  // the covariance, zero in the row and column of a fixed n
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  cov.topLeftCorner(p, p) = rss / static_cast<double>(f.points - unknowns) * lu.inverse();
  f.ok = true;
  f.A = q[0], f.k = q[1], f.n = m.n(q);
  f.A_error = std::sqrt(cov(0, 0)), f.k_error = std::sqrt(cov(1, 1));
  f.n_error = p == 3 ? std::sqrt(cov(2, 2)) : 0.0;
  // C = A d^-n: dC/dA = d^-n, dC/dn = -C ln d
  f.C = f.A * std::pow(d, -f.n);
  const double gA = std::pow(d, -f.n), gn = -f.C * std::log(d);
  f.C_error = std::sqrt(gA * gA * cov(0, 0) + gn * gn * cov(2, 2) + 2.0 * gA * gn * cov(0, 2));
  f.rms = std::sqrt(rss / static_cast<double>(f.points));
  return f;
}

double beverloo_rate(const BeverlooFit& f, double D, double d) {
  const double u = D / d - f.k;
  return u > 0.0 ? f.A * std::pow(u, f.n) : 0.0;
}

} // namespace talus
