#pragma once
// Tangential contact laws: friction force along t from the slip velocity and, for the spring
// laws, the stored tangential displacement (the contact's history, a scalar along the current
// tangent, so it is always kept in the current tangent direction). Like the normal laws, they
// take one contact or several side by side (number.hpp).
#include <string_view>

#include "talus/contact_geometry.hpp"
#include "talus/number.hpp"

namespace talus {

/// The thesis' viscous Coulomb law (eq. 2.11-2.12): F_t = -sign(v_t) min(eta_t |v_t|, mu F_n),
/// eta_t = gamma_t m_eff. No history: no static friction.
struct ViscousCoulomb {
  static constexpr std::string_view name = "coulomb";
  static constexpr bool has_history = false;
  static constexpr bool uses_r_eff = false;
  template <class P, class G, class R>
  static R force(const P& p, const G& g, R normal_force, R /*normal_stiffness*/, R& /*history*/,
                 double /*dt*/) {
    const R viscous = p.tangential_damping * g.m_eff * magnitude(g.v_tangent);
    const R f = smaller(viscous, p.friction * normal_force);
    return select(g.v_tangent > 0.0, -f, select(g.v_tangent < 0.0, f, R{}));
  }
  template <class P, class G, class R> static R stiffness(const P&, const G&, R) { return R{}; }
};

/// A tangential spring with history and Coulomb slip (Cundall & Strack 1979, as in LAMMPS):
/// s += v_t dt; F_t = -k_t s - eta_t v_t; if |F_t| > mu F_n, F_t = +-mu F_n and the spring is
/// reset to carry it: s = -(F_t + eta_t v_t) / k_t. `Stiffness` gives k_t.
template <class Stiffness> struct TangentialSpring {
  static constexpr bool has_history = true;
  static constexpr bool uses_r_eff = Stiffness::uses_r_eff;
  template <class P, class G, class R> static R stiffness(const P& p, const G& g, R kn) {
    return Stiffness::of(p, g, kn);
  }
  // the slip by selects, not a branch: two contacts side by side may differ (the reset spring
  // is computed for a contact that sticks too, and not used)
  template <class P, class G, class R>
  static R force(const P& p, const G& g, R normal_force, R kn, R& s, double dt) {
    const R kt = Stiffness::of(p, g, kn);
    const R eta = p.tangential_damping * g.m_eff;
    s += g.v_tangent * dt;
    const R f = -kt * s - eta * g.v_tangent;
    const R limit = p.friction * normal_force;
    const auto slips = magnitude(f) > limit;
    const R f_slip = copy_sign(limit, f);
    s = select(slips, select(kt > 0.0, -(f_slip + eta * g.v_tangent) / kt, R{}), s);
    return select(slips, f_slip, f);
  }
};

/// Cundall-Strack: k_t = ratio x k_n (linear law) or ratio x tangent stiffness (Hertz).
struct CundallStrackStiffness {
  static constexpr bool uses_r_eff = false;
  template <class P, class G, class R> static R of(const P& p, const G&, R kn) {
    return p.tangential_stiffness_ratio * kn;
  }
};
/// Hertz-Mindlin no-slip: k_t = 8 G* sqrt(R* xi).
struct MindlinStiffness {
  static constexpr bool uses_r_eff = true;
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
  static constexpr bool uses_r_eff = false;
  template <class P, class G, class R>
  static R force(const P&, const G&, R, R, R& /*history*/, double /*dt*/) {
    return R{};
  }
  template <class P, class G, class R> static R stiffness(const P&, const G&, R) { return R{}; }
};

} // namespace talus
