#include "scenario/timestep_accuracy.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "talus/law_table.hpp"
#include "talus/pair_parameters.hpp"

namespace talus {

namespace {

// t_c / dt and the largest relative restitution error of Gear and Verlet over four phases of the
// touch, viscoelastic Hertz two-disk impact (docs/accuracy.md, hertz_impact; made by
// /usr/bin/python3 validation/work_precision.py on 2026-12-03).
constexpr std::array<std::pair<double, double>, 8> hertz_measured{{{5, 1.8e-2},
                                                                   {10, 3.5e-3},
                                                                   {20, 4.8e-4},
                                                                   {50, 5.8e-5},
                                                                   {100, 1.3e-5},
                                                                   {200, 4.7e-6},
                                                                   {500, 6.6e-7},
                                                                   {1000, 2.5e-7}}};

// The largest damping ratio of the linear dashpot over the pairs that can meet, for grains of
// the lightest mass m_min (the rate part grows with the mass: this is its smallest).
double largest_damping_ratio(const BuiltScenario& b, double m_min) {
  double zeta = 0.0;
  for (const MeetingPair& m : meeting_pairs(b.world)) {
    const PairParameters p = mix(b.world.materials[m.a], b.world.materials[m.b], 1.0);
    const double m_eff = m.wall ? m_min : 0.5 * m_min;
    if (p.normal_stiffness > 0.0)
      zeta =
          std::max(zeta, p.normal_dashpot(m_eff) / (2.0 * std::sqrt(p.normal_stiffness * m_eff)));
  }
  return zeta;
}

} // namespace

double hertz_restitution_error(double factor) {
  const auto& t = hertz_measured;
  if (factor <= t.front().first) return t.front().second;
  if (factor >= t.back().first) return t.back().second * std::pow(t.back().first / factor, 2.0);
  for (std::size_t k = 1; k < t.size(); ++k)
    if (factor <= t[k].first) {
      const double f = std::log(factor / t[k - 1].first) / std::log(t[k].first / t[k - 1].first);
      return t[k - 1].second * std::pow(t[k].second / t[k - 1].second, f);
    }
  return t.back().second;
}

RestitutionError expected_restitution_error(const BuiltScenario& b) {
  const double factor = b.collision_time / b.config.timestep;
  if (b.config.normal_law == law_id<HertzViscoelastic>)
    return {hertz_restitution_error(factor), "Hertz, second order in dt, as measured at e = 0.99"};
  if (b.config.normal_law != law_id<LinearSpringDashpot>) return {};
  const Particles& p = b.world.particles;
  double m_min = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i)) m_min = std::min(m_min, p.mass[i]);
  if (m_min == std::numeric_limits<double>::max()) return {};
  const double zeta = largest_damping_ratio(b, m_min);
  const double onset = std::numbers::pi * zeta / factor;
  // an undamped spring (zeta 0 to rounding) has no jump: second order, not measured yet
  if (!(onset > 1e-12)) return {};
  return {onset, fmt::format("the dashpot's onset, pi zeta dt / t_c with zeta = {:.3g}", zeta)};
}

} // namespace talus
