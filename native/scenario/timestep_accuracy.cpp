#include "scenario/timestep_accuracy.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "talus/closed_forms.hpp"
#include "talus/law_table.hpp"
#include "talus/pair_parameters.hpp"

namespace talus {

namespace {

// The largest relative restitution error of Gear and Verlet over four phases of the touch, in a
// viscoelastic Hertz two-disk head-on impact at 2 x 0.05 m/s whose damping is derived from the
// restitution e, at t_c / dt from 5 to 1000 (columns) and e from 0.1 to 0.99 (rows); t_c is the
// elastic collision time the automatic timestep divides (docs/accuracy.md; made with
// validation/work_precision.py's hertz_impact scenario on 2026-12-04, its damping replaced by
// hertz_damping = -1 and the restitution).
constexpr std::array<double, 8> hertz_factors{5, 10, 20, 50, 100, 200, 500, 1000};
constexpr std::array<double, 8> hertz_restitutions{0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 0.95, 0.99};
constexpr std::array<std::array<double, 8>, 8> hertz_measured{{
    {1.74e1, 8.91, 1.15, 6.77e-3, 2.02e-3, 1.09e-3, 1.54e-4, 7.13e-5},
    {6.91, 2.00, 2.84e-2, 4.94e-3, 1.41e-3, 6.31e-4, 1.01e-4, 4.18e-5},
    {3.69, 5.19e-1, 2.09e-2, 3.65e-3, 1.07e-3, 4.47e-4, 7.37e-5, 2.91e-5},
    {7.07e-1, 4.16e-2, 1.13e-2, 2.22e-3, 6.26e-4, 2.34e-4, 4.31e-5, 1.58e-5},
    {9.58e-2, 2.54e-2, 5.81e-3, 1.18e-3, 3.47e-4, 1.25e-4, 2.15e-5, 7.65e-6},
    {3.69e-2, 8.55e-3, 2.04e-3, 3.55e-4, 1.11e-4, 3.90e-5, 7.00e-6, 2.43e-6},
    {2.56e-2, 5.17e-3, 1.18e-3, 2.32e-4, 4.82e-5, 1.88e-5, 2.92e-6, 1.21e-6},
    {1.78e-2, 3.48e-3, 4.79e-4, 5.89e-5, 1.32e-5, 4.87e-6, 6.52e-7, 2.54e-7},
}};

// One row of the table at t_c / dt = factor: log-log between its points; before the first, the
// first; beyond the last, the second-order trend.
double along_factor(const std::array<double, 8>& row, double factor) {
  const auto& f = hertz_factors;
  if (factor <= f.front()) return row.front();
  if (factor >= f.back()) return row.back() * std::pow(f.back() / factor, 2.0);
  std::size_t k = 1;
  while (factor > f[k]) ++k;
  const double w = std::log(factor / f[k - 1]) / std::log(f[k] / f[k - 1]);
  return row[k - 1] * std::pow(row[k] / row[k - 1], w);
}

// The lowest restitution of the Hertz law over the pairs that can meet, at the impact speed,
// for grains of the lightest mass and the smallest radius (a derived damping gives every pair
// its mean restitution there; a given A gives each its own).
double lowest_hertz_restitution(const BuiltScenario& b, double m_min, double r_min) {
  double lowest = 1.0;
  const double v = b.config.impact_speed;
  for (const MeetingPair& m : meeting_pairs(b.world)) {
    const PairParameters& p = b.pairs(m.a, m.b);
    const double m_eff = m.wall ? m_min : 0.5 * m_min, r_eff = m.wall ? r_min : 0.5 * r_min;
    const double rho = hertz_rho(p.effective_young, r_eff);
    const double A = HertzViscoelastic::damping(p, m_eff, rho);
    lowest = std::min(lowest, hertz_restitution(A, m_eff, rho, v));
  }
  return lowest;
}

// The largest damping ratio of the linear dashpot over the pairs that can meet, for grains of
// the lightest mass m_min (the rate part grows with the mass: this is its smallest).
double largest_damping_ratio(const BuiltScenario& b, double m_min) {
  double zeta = 0.0;
  for (const MeetingPair& m : meeting_pairs(b.world)) {
    const PairParameters& p = b.pairs(m.a, m.b);
    const double m_eff = m.wall ? m_min : 0.5 * m_min;
    if (p.normal_stiffness > 0.0)
      zeta =
          std::max(zeta, p.normal_dashpot(m_eff) / (2.0 * std::sqrt(p.normal_stiffness * m_eff)));
  }
  return zeta;
}

} // namespace

double hertz_restitution_error(double factor, double restitution) {
  const auto& e = hertz_restitutions;
  const double r = std::clamp(restitution, e.front(), e.back());
  std::size_t k = 1;
  while (k + 1 < e.size() && r > e[k]) ++k;
  const double low = along_factor(hertz_measured[k - 1], factor);
  const double high = along_factor(hertz_measured[k], factor);
  return low * std::pow(high / low, (r - e[k - 1]) / (e[k] - e[k - 1]));
}

RestitutionError expected_restitution_error(const BuiltScenario& b) {
  const double factor = b.collision_time / b.config.timestep;
  const bool hertz = b.config.normal_law == law_id<HertzViscoelastic>;
  if (!hertz && b.config.normal_law != law_id<LinearSpringDashpot>) return {};
  const Particles& p = b.world.particles;
  double m_min = std::numeric_limits<double>::max(), r_min = m_min;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i)) {
      m_min = std::min(m_min, p.mass[i]);
      r_min = std::min(r_min, p.radius[i]);
    }
  if (m_min == std::numeric_limits<double>::max()) return {};
  if (hertz) {
    const double e = lowest_hertz_restitution(b, m_min, r_min);
    return {hertz_restitution_error(factor, e),
            fmt::format("Hertz at e = {:.3g}, as measured from e = 0.1 to 0.99", e)};
  }
  const double zeta = largest_damping_ratio(b, m_min);
  const double onset = std::numbers::pi * zeta / factor;
  // an undamped spring (zeta 0 to rounding) has no jump: second order, not measured yet
  if (!(onset > 1e-12)) return {};
  return {onset, fmt::format("the dashpot's onset, pi zeta dt / t_c with zeta = {:.3g}", zeta)};
}

} // namespace talus
