#pragma once
// Tangential contact laws: friction force along t from the slip velocity and, for the spring
// laws, the stored tangential displacement (the contact's history). In 2D the tangential
// velocity, force and spring are scalars along the current tangent t (so the spring is always
// kept in the current tangent direction); in 3D they are vectors in the tangent plane
// (vector3.hpp; contact_force.hpp turns the spring into the plane as the contact turns). The
// same lines serve both: magnitude, copy_sign, select and opposing take either. Like the normal
// laws, they take one contact or several side by side (number.hpp). Each law is given the normal
// law N of its contact, whose stiffness a spring may follow.
#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

#include "talus/contact_geometry.hpp"
#include "talus/material.hpp"
#include "talus/number.hpp"
#include "talus/vector3.hpp"

namespace talus {

/// The thesis' viscous Coulomb law (eq. 2.11-2.12): F_t = -sign(v_t) min(eta_t |v_t|, mu F_n),
/// eta_t = gamma_t m_eff. No history: no static friction.
struct ViscousCoulomb {
  static constexpr std::string_view name = "coulomb";
  static constexpr bool has_history = false;
  static constexpr bool has_friction = true;
  static constexpr bool uses_r_eff = false;
  template <class N, class P, class G, class R, class H>
  static H force(const P& p, const G& g, R normal_force, H& /*history*/, double /*dt*/) {
    const R viscous = p.tangential_damping * g.m_eff * magnitude(g.v_tangent);
    const R f = smaller(viscous, p.friction * normal_force);
    return opposing(f, g.v_tangent);
  }
  template <class P, class G, class R> static R stiffness(const P&, const G&, R) { return R{}; }
  /// What is wrong with a material for this law ("" if nothing).
  static std::string material_error(const Material& m) {
    if (m.tangential_damping < 0.0)
      return "material '" + m.name +
             "': tangential_damping = -1 (from restitution) needs a tangential spring to damp; "
             "allowed with tangential law 'coulomb': >= 0 1/s (or choose tangential law "
             "'cundall_strack' or 'mindlin')";
    return {};
  }
};

/// A tangential spring with history and Coulomb slip, in the incremental form the literature
/// validates (Thornton et al. 2011 and 2013; LAMMPS' `mindlin_rescale/force`). The history s is
/// the spring's stretch, its force -k_t s. Each step:
/// - loading (k_t grew since the step before): s *= k_t,before / k_t, so that the spring's force
///   is kept and only the new stretch is taken at the new stiffness, dF = -k_t ds;
/// - unloading (k_t fell): s is kept, so that the force falls with the stiffness and reaches zero
///   with the contact;
/// - s += v_t dt; a spring beyond mu F_n is cut back to it (slip: s = -+mu F_n / k_t);
/// - F_t = -k_t s - eta_t v_t, itself capped at mu F_n (the dashpot's share is cut).
/// The spring alone is held within the Coulomb cone, as in LIGGGHTS and Thornton's models, so no
/// step raises the spring's energy 1/2 k_t s^2 beyond the work done on it and friction's
/// dissipation is never negative; the dashpot always opposes v_t. The damping
/// eta_t = gamma_t m_eff + f_N c sqrt(k_t m_eff) (c from the restitution, Tsuji et al. 1992).
/// `Stiffness` gives k_t.
template <class Stiffness> struct TangentialSpring {
  static constexpr bool has_history = true;
  static constexpr bool has_friction = true;
  static constexpr bool uses_r_eff = Stiffness::uses_r_eff;
  template <class P, class G, class R> static R stiffness(const P& p, const G& g, R kn) {
    return Stiffness::of(p, g, kn);
  }
  /// eta_t, kg/s, for a spring of stiffness kt beside the normal law N.
  template <class N, class P, class G, class R> static R dashpot(const P& p, const G& g, R kt) {
    const R rate_part = p.tangential_damping * g.m_eff;
    if (all_zero(p.tangential_damping_sqrt_coeff)) return rate_part;
    return rate_part +
           (N::tsuji_factor * p.tangential_damping_sqrt_coeff) * square_root(kt * g.m_eff);
  }
  // the slip by selects, not a branch: two contacts side by side may differ. H: the spring's
  // type, R in 2D, a vector of R in 3D
  template <class N, class P, class G, class R, class H>
  static H force(const P& p, const G& g, R normal_force, H& s, double dt) {
    const R kt = Stiffness::of(p, g, N::stiffness(p, g));
    const R limit = p.friction * normal_force;
    H spring;
    if constexpr (Stiffness::template follows_overlap<N>) {
      G before = g; // the overlap one step before, from its rate
      before.overlap = not_below_zero(g.overlap - g.overlap_rate() * dt);
      const R kt_before = Stiffness::of(p, before, N::stiffness(p, before));
      // loading keeps the force (k_t,before s), unloading the stretch (k_t s): the smaller
      spring = -smaller(kt, kt_before) * s - kt * (g.v_tangent * dt);
      spring = select(magnitude(spring) > limit, copy_sign(limit, spring), spring);
      s = select(kt > 0.0, -spring / kt, H{});
    } else {
      s += g.v_tangent * dt;
      spring = -kt * s;
      const auto slips = magnitude(spring) > limit;
      spring = select(slips, copy_sign(limit, spring), spring);
      s = select(slips, select(kt > 0.0, -spring / kt, H{}), s);
    }
    const H f = spring - dashpot<N>(p, g, kt) * g.v_tangent;
    return select(magnitude(f) > limit, copy_sign(limit, f), f);
  }
  static std::string material_error(const Material&) { return {}; }
};

/// Cundall-Strack: k_t = ratio x k_n (linear law) or ratio x tangent stiffness (Hertz).
struct CundallStrackStiffness {
  static constexpr bool uses_r_eff = false;
  template <class N> static constexpr bool follows_overlap = N::stiffness_follows_overlap;
  template <class P, class G, class R> static R of(const P& p, const G&, R kn) {
    return p.tangential_stiffness_ratio * kn;
  }
};
/// Hertz-Mindlin no-slip: k_t = 8 G* sqrt(R* xi).
struct MindlinStiffness {
  static constexpr bool uses_r_eff = true;
  template <class N> static constexpr bool follows_overlap = true;
  template <class P, class G, class R> static R of(const P& p, const G& g, R) {
    return 8.0 * p.effective_shear * square_root(g.r_eff * g.overlap);
  }
};

/// Cundall-Strack: k_t = ratio x k_n (linear law) or ratio x tangent stiffness (Hertz).
struct CundallStrack : TangentialSpring<CundallStrackStiffness> {
  static constexpr std::string_view name = "cundall_strack";
};
/// Hertz-Mindlin no-slip: k_t = 8 G* sqrt(R* xi).
struct MindlinNoSlip : TangentialSpring<MindlinStiffness> {
  static constexpr std::string_view name = "mindlin";
};

/// No tangential force and no torque: frictionless grains, as in jamming studies.
struct Frictionless {
  static constexpr std::string_view name = "none";
  static constexpr bool has_history = false;
  static constexpr bool has_friction = false;
  static constexpr bool uses_r_eff = false;
  template <class N, class P, class G, class R, class H>
  static H force(const P&, const G&, R, H& /*history*/, double /*dt*/) {
    return H{};
  }
  template <class P, class G, class R> static R stiffness(const P&, const G&, R) { return R{}; }
  static std::string material_error(const Material&) { return {}; }
};

/// The factor c of the tangential dashpot eta_t = f_N c sqrt(k_t m_eff) that a spring law takes
/// from the restitution e: c = 2 |ln e| / sqrt(ln^2 e + pi^2), twice the damping ratio of a
/// linear oscillator of that restitution. f_N is the normal law's `tsuji_factor`: 1 for the
/// linear law, sqrt(5/6) for Hertz (Tsuji et al. 1992, as EDEM and LIGGGHTS take it).
inline double tangential_damping_from_restitution(double restitution) {
  const double log_e = std::log(restitution);
  return 2.0 * -log_e / std::sqrt(log_e * log_e + std::numbers::pi * std::numbers::pi);
}

} // namespace talus
