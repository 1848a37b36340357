#include "post/beverloo.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include <fmt/core.h>

namespace talus {

namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;

// Solves M x = r for the first `p` unknowns by Gaussian elimination with partial pivoting;
// false when M is singular.
bool solve(Mat3 m, Vec3 r, std::size_t p, Vec3& x) {
  for (std::size_t c = 0; c < p; ++c) {
    std::size_t pivot = c;
    for (std::size_t i = c + 1; i < p; ++i)
      if (std::abs(m[i][c]) > std::abs(m[pivot][c])) pivot = i;
    if (!(std::abs(m[pivot][c]) > 0.0)) return false;
    std::swap(m[c], m[pivot]), std::swap(r[c], r[pivot]);
    for (std::size_t i = c + 1; i < p; ++i) {
      const double f = m[i][c] / m[c][c];
      for (std::size_t j = c; j < p; ++j) m[i][j] -= f * m[c][j];
      r[i] -= f * r[c];
    }
  }
  for (std::size_t c = p; c-- > 0;) {
    double s = r[c];
    for (std::size_t j = c + 1; j < p; ++j) s -= m[c][j] * x[j];
    x[c] = s / m[c][c];
  }
  return true;
}

// The model's parameters in the order (A, k, n); p = 2 leaves n out.
struct Model {
  const std::vector<double>& x; // D/d
  const std::vector<double>& W;
  double n_fixed;
  std::size_t p;

  double n(const Vec3& q) const { return p == 3 ? q[2] : n_fixed; }
  double rss(const Vec3& q) const {
    double s = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double e = W[i] - q[0] * std::pow(x[i] - q[1], n(q));
      s += e * e;
    }
    return s;
  }
  // J^T J and J^T e at q, e the residuals
  void normal(const Vec3& q, Mat3& jtj, Vec3& jte) const {
    jtj = {}, jte = {};
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double u = x[i] - q[1], un = std::pow(u, n(q));
      const Vec3 j{un, -q[0] * n(q) * un / u, q[0] * un * std::log(u)};
      const double e = W[i] - q[0] * un;
      for (std::size_t a = 0; a < p; ++a) {
        jte[a] += j[a] * e;
        for (std::size_t b = 0; b < p; ++b) jtj[a][b] += j[a] * j[b];
      }
    }
  }
};

} // namespace

BeverlooFit fit_beverloo(const std::vector<double>& D, const std::vector<double>& W, double d,
                         std::optional<double> fixed_n) {
  BeverlooFit f;
  f.n_fixed = fixed_n.has_value();
  f.points = std::min(D.size(), W.size());
  const std::size_t p = fixed_n ? 2 : 3;
  std::vector<double> x;
  for (std::size_t i = 0; i < f.points; ++i) x.push_back(D[i] / d);
  const std::set<double> widths(x.begin(), x.end());
  if (!(d > 0.0) || f.points <= p || widths.size() < p) {
    f.why_not = fmt::format("a fit with {} free parameters needs more than {} runs over at least "
                            "{} orifice widths (got {} runs, {} widths)",
                            p, p, p, f.points, widths.size());
    return f;
  }
  const Model m{x, W, fixed_n.value_or(1.5), p};
  const double x_min = *widths.begin();
  Vec3 q{0.0, std::min(1.5, 0.5 * x_min), m.n_fixed};
  { // A from the linear least squares at the starting k and n
    double su = 0.0, sw = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double u = std::pow(x[i] - q[1], q[2]);
      su += u * u, sw += u * W[i];
    }
    q[0] = sw / su;
  }
  double lambda = 1e-3, rss = m.rss(q);
  for (int it = 0; it < 500; ++it) {
    Mat3 jtj;
    Vec3 jte, step{};
    m.normal(q, jtj, jte);
    Mat3 damped = jtj;
    for (std::size_t a = 0; a < p; ++a) damped[a][a] *= 1.0 + lambda;
    if (!solve(damped, jte, p, step)) break;
    Vec3 next = q;
    for (std::size_t a = 0; a < p; ++a) next[a] += step[a];
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
  Mat3 jtj, cov{};
  Vec3 jte;
  m.normal(q, jtj, jte);
  const double s2 = rss / static_cast<double>(f.points - p);
  for (std::size_t c = 0; c < p; ++c) { // the covariance, column by column
    Vec3 unit{}, col{};
    unit[c] = 1.0;
    if (!solve(jtj, unit, p, col)) {
      f.why_not = "the fit is degenerate (the rates do not determine the parameters)";
      return f;
    }
    for (std::size_t r = 0; r < p; ++r) cov[r][c] = s2 * col[r];
  }
  f.ok = true;
  f.A = q[0], f.k = q[1], f.n = m.n(q);
  f.A_error = std::sqrt(cov[0][0]), f.k_error = std::sqrt(cov[1][1]);
  f.n_error = p == 3 ? std::sqrt(cov[2][2]) : 0.0;
  // C = A d^-n: dC/dA = d^-n, dC/dn = -C ln d
  f.C = f.A * std::pow(d, -f.n);
  const double gA = std::pow(d, -f.n), gn = -f.C * std::log(d);
  f.C_error = std::sqrt(gA * gA * cov[0][0] + gn * gn * cov[2][2] + 2.0 * gA * gn * cov[0][2]);
  f.rms = std::sqrt(rss / static_cast<double>(f.points));
  return f;
}

double beverloo_rate(const BeverlooFit& f, double D, double d) {
  const double u = D / d - f.k;
  return u > 0.0 ? f.A * std::pow(u, f.n) : 0.0;
}

} // namespace talus
