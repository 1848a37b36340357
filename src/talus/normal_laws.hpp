#pragma once
// Normal contact laws: the magnitude of the repulsive force from the overlap and its rate, and
// what a run needs to know of each law before it starts (its collision time, its stiffest
// oscillation, the material values it requires). `force` and `stiffness` take one contact or
// several side by side (number.hpp); the same lines serve both.
#include <cmath>
#include <string>
#include <string_view>

#include "talus/closed_forms.hpp"
#include "talus/contact_geometry.hpp"
#include "talus/material.hpp"
#include "talus/pair_parameters.hpp"
#include "talus/words.hpp"

namespace talus {

/// Linear spring-dashpot (thesis eq. 2.10): F_n = k_n xi + eta_n dxi/dt, never attractive but
/// with the classic convention (LinearDamping, pair_parameters.hpp), which lets it pull.
/// eta_n = gamma_n m_eff, or 2 zeta sqrt(k_n m_eff) from the restitution (closed_forms.hpp).
struct LinearSpringDashpot {
  static constexpr std::string_view name = "linear";
  static constexpr int thesis_force_law = 1; ///< its number in the thesis' input files
  /// The material key that sets its stiffness, and how the peak overlap of an impact goes with
  /// it: overlap ~ key^(-1 / stiffness_power).
  static constexpr double Material::*stiffness_key = &Material::normal_stiffness;
  static constexpr const char* stiffness_name = "normal_stiffness";
  static constexpr const char* stiffness_unit = "N/m";
  static constexpr double stiffness_power = 2.0;
  static constexpr bool uses_r_eff = false;
  /// Whether the stiffness k_n changes with the overlap (a spring following it then rescales).
  static constexpr bool stiffness_follows_overlap = false;
  /// f_N of a tangential dashpot derived from the restitution (tangential_laws.hpp): the linear
  /// oscillator's own damping ratio.
  static constexpr double tsuji_factor = 1.0;
  /// Whether the force may be negative (a pull), which a friction limit must not take.
  static constexpr bool can_pull = true;
  template <class P, class G> static auto force(const P& p, const G& g) {
    const auto f = p.normal_stiffness * g.overlap + p.normal_dashpot(g.m_eff) * g.overlap_rate();
    // not below the floor: 0, as not_below_zero, but for the classic dashpot's -infinity
    return select(f < p.normal_force_floor, p.normal_force_floor, f);
  }
  /// Normal stiffness k_n seen by a tangential spring.
  template <class P, class G> static auto stiffness(const P& p, const G&) {
    return p.normal_stiffness;
  }
  template <class G> static double elastic_energy(const PairParameters& p, const G& g) {
    return 0.5 * p.normal_stiffness * g.overlap * g.overlap;
  }
  /// Duration of a contact of reduced mass m_eff (any impact speed).
  static double collision_time(const PairParameters& p, double m_eff, double /*r_eff*/,
                               double /*impact_speed*/) {
    if (p.normal_force_floor < 0.0) // a dashpot that pulls keeps the contact to pi / omega
      return linear_collision_time_textbook(p.normal_stiffness, p.normal_dashpot(m_eff), m_eff);
    return linear_collision_time(p.normal_stiffness, p.normal_dashpot(m_eff), m_eff);
  }
  /// The stiffness of the stiffest oscillation of such a contact, for the timestep's bound.
  static double peak_stiffness(const PairParameters& p, double, double, double) {
    return p.normal_stiffness;
  }
  /// The largest overlap of an undamped impact at impact_speed: v sqrt(m_eff / k_n).
  static double peak_overlap(const PairParameters& p, double m_eff, double /*r_eff*/,
                             double impact_speed) {
    return impact_speed * std::sqrt(m_eff / p.normal_stiffness);
  }
  /// What is wrong with a material for this law with the damping convention d ("" if nothing).
  static std::string material_error(const Material& m,
                                    LinearDamping d = LinearDamping::never_attractive) {
    if (!(m.normal_stiffness > 0.0))
      return "material '" + m.name +
             "': normal_stiffness must be > 0 N/m for the linear normal law (or choose normal "
             "law 'hertz')";
    if (d == LinearDamping::never_attractive &&
        !(m.normal_damping_rate >= 0.0 || m.restitution > linear_restitution_floor))
      return "material '" + m.name + "': restitution = " + std::to_string(m.restitution) +
             " cannot be reached by the never-attractive linear spring-dashpot; allowed: "
             "(0.1354, 1] (or simulation.linear_damping = \"classic\", whose dashpot pulls)";
    return {};
  }
  /// Fills in a damping left to be derived (negative): the linear law takes its damping from the
  /// restitution when the pair is mixed, so the Hertz constant is unused.
  static void resolve_damping(Material& m) {
    if (m.hertz_damping < 0.0) m.hertz_damping = 0.0;
  }
  /// Whether a damping derived from the restitution depends on the impact speed.
  static constexpr bool damping_needs_impact_speed = false;
  /// The pair's damping in words, for a contact of `who` (m_eff, r_eff), as a run reports it.
  static std::string describe_damping(const PairParameters& p, double /*m_eff*/, double /*r_eff*/,
                                      double /*impact_speed*/, const char* /*who*/) {
    if (p.damping_sqrt_coeff > 0.0)
      return format_words("eta_n = 2 zeta sqrt(k_n m_eff), zeta = %.6g",
                          p.damping_sqrt_coeff / (2.0 * std::sqrt(p.normal_stiffness)));
    return format_words("eta_n = gamma_n m_eff, gamma_n = %.6g 1/s", p.damping_rate);
  }
};

/// Hertzian viscoelastic (Brilliantov et al. 1996; thesis eq. 2.9):
/// F_n = rho (xi^3/2 + 3/2 A sqrt(xi) dxi/dt), rho = 4/3 E* sqrt(R*), never attractive.
struct HertzViscoelastic {
  static constexpr std::string_view name = "hertz";
  static constexpr int thesis_force_law = 0;
  static constexpr double Material::*stiffness_key = &Material::young;
  static constexpr const char* stiffness_name = "young";
  static constexpr const char* stiffness_unit = "Pa";
  static constexpr double stiffness_power = 2.5; ///< overlap ~ E^(-2/5)
  static constexpr bool uses_r_eff = true;
  static constexpr bool stiffness_follows_overlap = true;
  static constexpr bool can_pull = false;
  /// sqrt(5/6): Tsuji et al. 1992's factor for a dashpot beside a Hertzian spring.
  static constexpr double tsuji_factor = 0.91287092917527685576;
  template <class P, class G> static auto force(const P& p, const G& g) {
    const auto rho = 4.0 / 3.0 * p.effective_young * square_root(g.r_eff);
    const auto s = square_root(g.overlap);
    const auto A = damping(p, g.m_eff, rho);
    return not_below_zero(rho * s * (g.overlap + 1.5 * A * g.overlap_rate()));
  }
  /// A, s, of a contact of reduced mass m_eff and rho = 4/3 E* sqrt(R*): the pair's constant
  /// part plus the part derived from the restitution, c (m_eff / rho)^(2/5).
  template <class P, class R> static R damping(const P& p, R m_eff, R rho) {
    R A = p.hertz_damping;
    if (!all_zero(p.hertz_damping_scale)) A = A + p.hertz_damping_scale * power(m_eff / rho, 0.4);
    return A;
  }
  /// Tangent stiffness dF/dxi = 2 E* sqrt(R* xi), used to scale a linear tangential spring.
  template <class P, class G> static auto stiffness(const P& p, const G& g) {
    return 2.0 * p.effective_young * square_root(g.r_eff * g.overlap);
  }
  template <class G> static double elastic_energy(const PairParameters& p, const G& g) {
    const double rho = 4.0 / 3.0 * p.effective_young * std::sqrt(g.r_eff);
    return 0.4 * rho * g.overlap * g.overlap * std::sqrt(g.overlap);
  }
  /// The elastic duration of an impact at impact_speed.
  static double collision_time(const PairParameters& p, double m_eff, double r_eff,
                               double impact_speed) {
    return hertz_collision_time(m_eff, hertz_rho(p.effective_young, r_eff), impact_speed);
  }
  /// dF/dxi at the largest overlap of an impact at impact_speed.
  static double peak_stiffness(const PairParameters& p, double m_eff, double r_eff,
                               double impact_speed) {
    const double rho = hertz_rho(p.effective_young, r_eff);
    return 1.5 * rho * std::sqrt(hertz_max_overlap(m_eff, rho, impact_speed));
  }
  /// The largest overlap of an undamped impact at impact_speed.
  static double peak_overlap(const PairParameters& p, double m_eff, double r_eff,
                             double impact_speed) {
    return hertz_max_overlap(m_eff, hertz_rho(p.effective_young, r_eff), impact_speed);
  }
  static std::string material_error(const Material&, LinearDamping = {}) { return {}; }
  /// A damping left to be derived (negative) stays so: the pair's A is then derived per contact
  /// from the restitution (mix_hertz_damping).
  static void resolve_damping(Material&) {}
  /// Whether a damping derived from the restitution depends on the impact speed: it reaches the
  /// restitution at one speed.
  static constexpr bool damping_needs_impact_speed = true;
  /// The pair's damping in words, for a contact of `who` (m_eff, r_eff), as a run reports it.
  static std::string describe_damping(const PairParameters& p, double m_eff, double r_eff,
                                      double impact_speed, const char* who) {
    if (p.hertz_damping_scale == 0.0) return format_words("A = %.6g s", p.hertz_damping);
    const double A = damping(p, m_eff, hertz_rho(p.effective_young, r_eff));
    return format_words("A = %.6g s for ", A) + who +
           format_words(" (per contact: A = %.6g + %.6g (m_eff / rho)^(2/5), reaching e at %.6g "
                        "m/s)",
                        p.hertz_damping, p.hertz_damping_scale, impact_speed);
  }
};

} // namespace talus
