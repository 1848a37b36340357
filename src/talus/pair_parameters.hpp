#pragma once
// Everything a contact law needs about a pair of materials, and how the pair's values are mixed
// from the two materials. One definition for any number type (number.hpp): the table of every
// pair holds doubles; an engine that computes several contacts side by side gathers them into its
// SIMD type with gather().
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>

#include "talus/closed_forms.hpp"
#include "talus/material.hpp"
#include "talus/number.hpp"
#include "talus/tangential_laws.hpp"

namespace talus {

/// How the linear law's dashpot is derived from a restitution, and whether it may pull
/// (docs/model.md, "Linear damping conventions"):
/// - never_attractive: the force is cut at zero and the dashpot chosen so that the contact has
///   exactly the restitution asked (e > exp(-2) only);
/// - classic: the closed form of Tsuji et al. 1992, LAMMPS and MFIX, zeta = -ln e /
///   sqrt(pi^2 + ln^2 e), with the force allowed to pull at the end of the contact, which gives
///   exactly e;
/// - classic_cut: the same dashpot with the force cut at zero, as LAMMPS' `limit_damping`: the
///   restitution comes out above the one asked.
/// A given gamma_n (normal_damping_rate) pulls with `classic` only.
enum class LinearDamping : std::uint8_t { never_attractive = 0, classic = 1, classic_cut = 2 };
inline constexpr std::array<std::string_view, 3> linear_damping_names{"never_attractive", "classic",
                                                                      "classic_cut"};
inline std::string_view to_string(LinearDamping d) {
  return linear_damping_names[static_cast<std::size_t>(d)];
}

/// Mixing rules (see docs/model.md): moduli by the Hertz and Mindlin series rules; stiffness k_n
/// by the harmonic mean (a material paired with itself keeps its own k_n); restitution, friction,
/// rolling resistance and damping by the arithmetic mean. A linear dashpot and a Hertz damping left
/// to be derived give the pair's mean restitution exactly, for any masses and sizes (the Hertz one
/// at the reference impact speed).
template <class R> struct PairParametersOf {
  R normal_stiffness{};                           ///< k_n, N/m
  R damping_rate{};                               ///< gamma_n, 1/s: eta_n += gamma_n m_eff
  R damping_sqrt_coeff{};                         ///< 2 zeta sqrt(k_n): eta_n += this * sqrt(m_eff)
  R tangential_stiffness_ratio = R{} + 2.0 / 7.0; ///< k_t / k_n (Cundall-Strack)
  R tangential_damping{};                         ///< gamma_t, 1/s: eta_t += gamma_t m_eff
  /// c, from the restitution: a spring law's eta_t += f_N c sqrt(k_t m_eff) (tangential_laws.hpp)
  R tangential_damping_sqrt_coeff{};
  R friction{};        ///< mu
  R effective_young{}; ///< E*, Pa
  R effective_shear{}; ///< G*, Pa
  R hertz_damping{};   ///< A, s: the constant part of A
  /// c, the part of A derived from the restitution: A += c (m_eff / rho)^(2/5) per contact
  R hertz_damping_scale{};
  R restitution = R{} + 1.0; ///< the mixed e (informational for the Hertz law)
  R rolling_friction{};      ///< mu_r (rolling_resistance.hpp); 0: no rolling resistance
  R rolling_stiffness_factor = R{} + 2.25; ///< k_r = this x k_n mu_r^2 R*^2
  R rolling_damping{};                     ///< eta_r: the rolling dashpot over its critical value
  /// N: the least normal force of the linear law: 0 (never attractive), or -infinity where the
  /// classic dashpot may pull (LinearDamping::classic)
  R normal_force_floor{};

  /// Linear dashpot coefficient eta_n (kg/s) for a pair of reduced mass m_eff.
  R normal_dashpot(R m_eff) const {
    const R rate_part = damping_rate * m_eff;
    if (all_zero(damping_sqrt_coeff)) return rate_part;
    return select(damping_sqrt_coeff == 0.0, rate_part,
                  rate_part + damping_sqrt_coeff * square_root(m_eff));
  }

  /// The parameters whose every field is f(a.field, b.field): how an engine puts the parameters
  /// of several contacts side by side (the one list of the fields besides their declaration).
  template <class S, class F>
  static PairParametersOf gather(const PairParametersOf<S>& a, const PairParametersOf<S>& b, F f) {
    return {f(a.normal_stiffness, b.normal_stiffness),
            f(a.damping_rate, b.damping_rate),
            f(a.damping_sqrt_coeff, b.damping_sqrt_coeff),
            f(a.tangential_stiffness_ratio, b.tangential_stiffness_ratio),
            f(a.tangential_damping, b.tangential_damping),
            f(a.tangential_damping_sqrt_coeff, b.tangential_damping_sqrt_coeff),
            f(a.friction, b.friction),
            f(a.effective_young, b.effective_young),
            f(a.effective_shear, b.effective_shear),
            f(a.hertz_damping, b.hertz_damping),
            f(a.hertz_damping_scale, b.hertz_damping_scale),
            f(a.restitution, b.restitution),
            f(a.rolling_friction, b.rolling_friction),
            f(a.rolling_stiffness_factor, b.rolling_stiffness_factor),
            f(a.rolling_damping, b.rolling_damping),
            f(a.normal_force_floor, b.normal_force_floor)};
  }
};
using PairParameters = PairParametersOf<double>;

/// Cundall-Strack's k_t / k_n of a pair, after its E* and G*: the mean of the materials' ratios,
/// where a material leaves its ratio to be derived (negative) its part is Mindlin's, the ratio of
/// the no-slip tangential stiffness 8 G* a to Hertz' normal tangent stiffness 2 E* a (Mindlin
/// 1949): 4 G* / E* of the pair when neither gives one, 2 (1 - nu) / (2 - nu) of the material
/// (its value against itself) when the other does.
inline void mix_tangential_stiffness_ratio(PairParameters& p, const Material& a,
                                           const Material& b) {
  const auto own = [](const Material& m) {
    return m.tangential_stiffness_ratio >= 0.0 ? m.tangential_stiffness_ratio
                                               : 2.0 * (1.0 - m.poisson) / (2.0 - m.poisson);
  };
  if (a.tangential_stiffness_ratio < 0.0 && b.tangential_stiffness_ratio < 0.0)
    p.tangential_stiffness_ratio = 4.0 * p.effective_shear / p.effective_young;
  else
    p.tangential_stiffness_ratio = 0.5 * (own(a) + own(b));
}

/// The Hertz damping of a pair: the mean of the materials' A, where a material leaves A to be
/// derived (negative) its part is the A that reaches a restitution at `impact_speed`, per contact
/// (closed_forms.hpp: A = c (m_eff / rho)^(2/5)): the pair's mean restitution when neither gives
/// A, the other material's own when one does.
inline void mix_hertz_damping(PairParameters& p, const Material& a, const Material& b,
                              double impact_speed) {
  const bool a_derived = a.hertz_damping < 0.0, b_derived = b.hertz_damping < 0.0;
  if (!a_derived && !b_derived) {
    p.hertz_damping = 0.5 * (a.hertz_damping + b.hertz_damping);
  } else if (a_derived && b_derived) {
    p.hertz_damping_scale = hertz_damping_scale(p.restitution, impact_speed);
  } else {
    const Material& given = a_derived ? b : a;
    const Material& derived = a_derived ? a : b;
    p.hertz_damping = 0.5 * given.hertz_damping;
    p.hertz_damping_scale = 0.5 * hertz_damping_scale(derived.restitution, impact_speed);
  }
}

/// The tangential damping of a pair: the mean of the materials' gamma_t, where a material leaves
/// it to be derived (negative) its part is the dashpot of Tsuji et al. 1992 from a restitution:
/// the pair's mean restitution when neither gives gamma_t, its own when the other does.
inline void mix_tangential_damping(PairParameters& p, const Material& a, const Material& b) {
  const bool a_derived = a.tangential_damping < 0.0, b_derived = b.tangential_damping < 0.0;
  if (!a_derived && !b_derived) {
    p.tangential_damping = 0.5 * (a.tangential_damping + b.tangential_damping);
  } else if (a_derived && b_derived) {
    p.tangential_damping_sqrt_coeff = tangential_damping_from_restitution(p.restitution);
  } else {
    const Material& given = a_derived ? b : a;
    const Material& derived = a_derived ? a : b;
    p.tangential_damping = 0.5 * given.tangential_damping;
    p.tangential_damping_sqrt_coeff =
        0.5 * tangential_damping_from_restitution(derived.restitution);
  }
}

/// The parameters of a contact between materials a and b (for a wall, b is its material). A rigid
/// material adds no compliance: against it the stiffness, E* and G* are the other material's
/// alone (E* = E / (1 - nu^2), G* = E / (2 (2 - nu) (1 + nu)), k_n its own); restitution,
/// friction and damping still mix by the mean. Two rigid materials never meet; their pair mixes
/// as if neither were rigid, so that it stays finite.
inline PairParameters mix(const Material& a, const Material& b, double impact_speed,
                          LinearDamping damping = LinearDamping::never_attractive) {
  if (a.rigid != b.rigid) {
    const Material& soft = a.rigid ? b : a;
    Material wall = a.rigid ? a : b; // its dissipation and friction mix as usual
    wall.rigid = false;
    wall.normal_stiffness = soft.normal_stiffness; // (the harmonic mean is then soft's own)
    PairParameters p = mix(soft, wall, impact_speed, damping);
    const double nu = soft.poisson;
    p.effective_young = soft.young / (1.0 - nu * nu);
    p.effective_shear = soft.young / (2.0 * (2.0 - nu) * (1.0 + nu));
    mix_tangential_stiffness_ratio(p, soft, wall);
    return p;
  }
  PairParameters p;
  const auto mean = [](double x, double y) { return 0.5 * (x + y); };
  if (a.normal_stiffness > 0.0 && b.normal_stiffness > 0.0)
    p.normal_stiffness =
        2.0 * a.normal_stiffness * b.normal_stiffness / (a.normal_stiffness + b.normal_stiffness);
  p.restitution = mean(a.restitution, b.restitution);
  if (a.normal_damping_rate >= 0.0 || b.normal_damping_rate >= 0.0) {
    p.damping_rate =
        mean(std::max(a.normal_damping_rate, 0.0), std::max(b.normal_damping_rate, 0.0));
  } else if (damping != LinearDamping::never_attractive) {
    p.damping_sqrt_coeff =
        2.0 * classic_damping_ratio(p.restitution) * std::sqrt(p.normal_stiffness);
  } else if (p.restitution > linear_restitution_floor) {
    p.damping_sqrt_coeff =
        2.0 * linear_damping_ratio(p.restitution) * std::sqrt(p.normal_stiffness);
  } // below the floor only the Hertz law reaches e; the linear law's material check refuses it
  if (damping == LinearDamping::classic)
    p.normal_force_floor = -std::numeric_limits<double>::infinity();
  mix_tangential_damping(p, a, b);
  p.friction = mean(a.friction, b.friction);
  p.rolling_friction = mean(a.rolling_friction, b.rolling_friction);
  p.rolling_stiffness_factor = mean(a.rolling_stiffness_factor, b.rolling_stiffness_factor);
  p.rolling_damping = mean(a.rolling_damping, b.rolling_damping);
  p.effective_young = effective_young(a, b);
  p.effective_shear = effective_shear(a, b);
  mix_tangential_stiffness_ratio(p, a, b);
  mix_hertz_damping(p, a, b, impact_speed);
  return p;
}

} // namespace talus
