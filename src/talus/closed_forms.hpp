#pragma once
// Single-contact closed forms of the normal laws: collision time, restitution <-> damping.
// m_eff = m_i m_j / (m_i + m_j), r_eff = R_i R_j / (R_i + R_j); for a wall, m_eff = m, r_eff = R.
//
// Linear spring-dashpot, m xi'' = -max(0, k xi + eta xi'): with beta = eta / (2 m),
// omega = sqrt(k/m - beta^2) and x = beta / omega. Because the force is never attractive, the
// grains part when it vanishes, before the overlap does (Schwager & Poeschel 2007, Granular
// Matter 9, 465): e = exp(-x (pi - 2 atan x)), and the overlap returns to zero after
// t_c = (pi - 2 atan x + sin(2 atan x)) / omega. For weak damping these tend to the textbook
// e = exp(-pi x) and t_c = pi / omega. The lowest reachable restitution is e^-2.
//
// Hertzian viscoelastic, m xi'' = -rho (xi^3/2 + 3/2 A sqrt(xi) xi'), rho = 4/3 E* sqrt(R*).
#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <string>

#include "talus/error.hpp"

namespace talus {

namespace closed_form_detail {
// -ln e as a function of x = beta / omega for the never-attractive dashpot; increasing in x.
inline double log_loss(double x) {
  return x * (std::numbers::pi - 2.0 * std::atan(x));
}
} // namespace closed_form_detail

/// The least restitution the never-attractive linear spring-dashpot reaches: exp(-2), as its
/// damping grows without bound.
inline const double linear_restitution_floor = std::exp(-2.0);

/// The damping ratio zeta = eta / (2 sqrt(k m)) that gives restitution e (exact, by bisection).
inline double linear_damping_ratio(double restitution) {
  const double e_min = linear_restitution_floor;
  require(restitution > e_min && restitution <= 1.0,
          "restitution = " + std::to_string(restitution) +
              " cannot be reached by the linear spring-dashpot; allowed: (0.1354, 1]");
  const double target = -std::log(restitution);
  double lo = 0.0, hi = 1.0;
  while (closed_form_detail::log_loss(hi) < target) hi *= 2.0;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (closed_form_detail::log_loss(mid) < target ? lo : hi) = mid;
  }
  const double x = 0.5 * (lo + hi);
  return x / std::sqrt(1.0 + x * x); // zeta = beta / omega_0
}

/// The damping ratio of the classic closed form, zeta = -ln e / sqrt(pi^2 + ln^2 e) (Tsuji et al.
/// 1992, LAMMPS, MFIX): the restitution of a dashpot allowed to pull at the end of the contact.
inline double classic_damping_ratio(double restitution) {
  require(restitution > 0.0 && restitution <= 1.0,
          "restitution = " + std::to_string(restitution) + "; allowed: (0, 1]");
  const double log_e = std::log(restitution);
  return -log_e / std::sqrt(std::numbers::pi * std::numbers::pi + log_e * log_e);
}

namespace closed_form_detail {
inline double damped_frequency(double stiffness, double dashpot, double m_eff) {
  const double beta = dashpot / (2.0 * m_eff);
  const double w2 = stiffness / m_eff - beta * beta;
  require(w2 > 0.0, "overdamped linear contact: restitution would be 0");
  return std::sqrt(w2);
}
} // namespace closed_form_detail

/// Restitution of the (never attractive) linear spring-dashpot contact.
inline double linear_restitution(double stiffness, double dashpot, double m_eff) {
  const double x =
      dashpot / (2.0 * m_eff) / closed_form_detail::damped_frequency(stiffness, dashpot, m_eff);
  return std::exp(-closed_form_detail::log_loss(x));
}

/// Duration of the overlap of the (never attractive) linear spring-dashpot contact.
inline double linear_collision_time(double stiffness, double dashpot, double m_eff) {
  const double w = closed_form_detail::damped_frequency(stiffness, dashpot, m_eff);
  const double delta = 2.0 * std::atan(dashpot / (2.0 * m_eff) / w);
  return (std::numbers::pi - delta + std::sin(delta)) / w;
}

/// The textbook values for a dashpot allowed to pull: e = exp(-pi beta/omega), t_c = pi/omega.
inline double linear_restitution_textbook(double stiffness, double dashpot, double m_eff) {
  const double beta = dashpot / (2.0 * m_eff);
  return std::exp(-std::numbers::pi * beta /
                  closed_form_detail::damped_frequency(stiffness, dashpot, m_eff));
}

inline double linear_collision_time_textbook(double stiffness, double dashpot, double m_eff) {
  return std::numbers::pi / closed_form_detail::damped_frequency(stiffness, dashpot, m_eff);
}

inline double hertz_rho(double effective_young, double r_eff) {
  return 4.0 / 3.0 * effective_young * std::sqrt(r_eff);
}

/// Elastic collision duration at impact speed v: t_c = c (m_eff / rho)^(2/5) v^(-1/5), with the
/// exact c = 2 (5/4)^(2/5) sqrt(pi) Gamma(7/5) / Gamma(9/10) = 3.2181 (2.868 in terms of E*, R*).
inline double hertz_collision_time(double m_eff, double rho, double impact_speed) {
  const double c =
      2.0 * std::pow(1.25, 0.4) * std::sqrt(std::numbers::pi) * std::tgamma(1.4) / std::tgamma(0.9);
  return c * std::pow(m_eff / rho, 0.4) * std::pow(impact_speed, -0.2);
}

/// Elastic maximum overlap: (5 m_eff v^2 / (4 rho))^(2/5).
inline double hertz_max_overlap(double m_eff, double rho, double impact_speed) {
  return std::pow(1.25 * m_eff * impact_speed * impact_speed / rho, 0.4);
}

namespace closed_form_detail {
// Dimensionless contact: x'' = -max(0, x^3/2 + D sqrt(x) x'), x(0) = 0, x'(0) = 1, with
// x = xi / xi*, xi* = (m v^2 / rho)^(2/5), tau = t v / xi*, D = 3/2 A v / xi*. Returns -x'(exit).
inline double dimensionless_restitution(double D) {
  const auto acc = [D](double x, double u) {
    if (x <= 0.0) return 0.0;
    const double s = std::sqrt(x);
    return -std::max(0.0, x * s + D * s * u);
  };
  const double h = 2.0e-5;
  double x = 0.0, u = 1.0;
  for (int step = 0; step < 10'000'000; ++step) {
    const double k1x = u, k1u = acc(x, u);
    const double k2x = u + 0.5 * h * k1u, k2u = acc(x + 0.5 * h * k1x, u + 0.5 * h * k1u);
    const double k3x = u + 0.5 * h * k2u, k3u = acc(x + 0.5 * h * k2x, u + 0.5 * h * k2u);
    const double k4x = u + h * k3u, k4u = acc(x + h * k3x, u + h * k3u);
    const double xn = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    const double un = u + h / 6.0 * (k1u + 2.0 * k2u + 2.0 * k3u + k4u);
    if (xn <= 0.0) {
      const double f = x / (x - xn); // linear interpolation to the crossing
      return -(u + f * (un - u));
    }
    x = xn;
    u = un;
  }
  return 0.0;
}
} // namespace closed_form_detail

/// Restitution of the viscoelastic law at impact speed v, by accurate integration of the
/// single-contact equation (relative error below 1e-8).
inline double hertz_restitution(double damping_A, double m_eff, double rho, double impact_speed) {
  require(damping_A >= 0.0 && m_eff > 0.0 && rho > 0.0 && impact_speed > 0.0,
          "hertz_restitution: A >= 0, m_eff > 0, rho > 0 and impact speed > 0 are required");
  const double xi_star = std::pow(m_eff * impact_speed * impact_speed / rho, 0.4);
  return closed_form_detail::dimensionless_restitution(1.5 * damping_A * impact_speed / xi_star);
}

/// The dimensionless damping D = 3/2 A v / xi* that gives restitution e in (0, 1]: the
/// viscoelastic law's restitution depends on the pair, its A and the impact speed only through D,
/// so one D serves every pair of that restitution. Found by the Illinois variant of regula falsi
/// on ln e(D), to a relative 1e-12 of D; each restitution is solved once per process.
inline double hertz_dimensionless_damping(double restitution) {
  require(restitution > 0.0 && restitution <= 1.0,
          "restitution = " + std::to_string(restitution) + " is out of range; allowed: (0, 1]");
  if (restitution == 1.0) return 0.0;
  static std::mutex guard;
  static std::map<double, double> solved;
  {
    const std::lock_guard<std::mutex> lock(guard);
    if (const auto it = solved.find(restitution); it != solved.end()) return it->second;
  }
  const double target = std::log(restitution);
  const auto miss = [&](double D) {
    return std::log(closed_form_detail::dimensionless_restitution(D)) - target;
  };
  double lo = 0.0, f_lo = -target, hi = 1.0, f_hi = miss(hi);
  while (f_hi > 0.0) {
    lo = hi, f_lo = f_hi, hi *= 4.0;
    require(hi < 1e9, "hertz_dimensionless_damping: no damping reaches that restitution");
    f_hi = miss(hi);
  }
  int kept_side = 0; // which end stayed on the last step: Illinois halves its value then
  double D = hi;
  for (int it = 0; it < 200 && hi - lo > 1e-12 * hi; ++it) {
    D = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    const double f = miss(D);
    if (f == 0.0) break;
    if (f > 0.0) { // D is below the root: it becomes lo
      lo = D, f_lo = f;
      if (kept_side == 1) f_hi *= 0.5;
      kept_side = 1;
    } else {
      hi = D, f_hi = f;
      if (kept_side == -1) f_lo *= 0.5;
      kept_side = -1;
    }
  }
  const std::lock_guard<std::mutex> lock(guard);
  solved.emplace(restitution, D);
  return D;
}

/// The A that gives restitution e at impact speed v for a pair of m_eff and rho:
/// A = 2/3 D(e) xi* / v, xi* = (m_eff v^2 / rho)^(2/5).
inline double hertz_damping_for_restitution(double restitution, double m_eff, double rho,
                                            double impact_speed) {
  require(m_eff > 0.0 && rho > 0.0 && impact_speed > 0.0,
          "hertz_damping_for_restitution: m_eff > 0, rho > 0 and impact speed > 0 are required");
  const double xi_star = std::pow(m_eff * impact_speed * impact_speed / rho, 0.4);
  return hertz_dimensionless_damping(restitution) * xi_star / (1.5 * impact_speed);
}

/// The factor c of A = c (m_eff / rho)^(2/5) that gives restitution e at impact speed v for any
/// pair: c = 2/3 D(e) v^(-1/5).
inline double hertz_damping_scale(double restitution, double impact_speed) {
  require(impact_speed > 0.0, "hertz_damping_scale: impact speed > 0 is required");
  return hertz_dimensionless_damping(restitution) / (1.5 * std::pow(impact_speed, 0.2));
}

} // namespace talus
