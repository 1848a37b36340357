#pragma once
// Tangential contact laws: friction force along t from the slip velocity and, for the spring
// laws, the stored tangential displacement (the contact's history, a scalar along the current
// tangent, so it is always kept in the current tangent direction).
#include <algorithm>
#include <cmath>

#include "contact/geometry.hpp"
#include "materials/pair_table.hpp"

namespace talus {

/// The thesis' viscous Coulomb law (eq. 2.11-2.12): F_t = -sign(v_t) min(eta_t |v_t|, mu F_n),
/// eta_t = gamma_t m_eff. No history: no static friction.
struct ViscousCoulomb {
  static constexpr bool has_history = false;
  static constexpr bool uses_r_eff = false;
  static double force(const PairParameters& p, const ContactGeometry& g, double normal_force,
                      double /*normal_stiffness*/, double& /*history*/, double /*dt*/) {
    const double viscous = p.tangential_damping * g.m_eff * std::abs(g.v_tangent);
    const double f = std::min(viscous, p.friction * normal_force);
    return g.v_tangent > 0.0 ? -f : (g.v_tangent < 0.0 ? f : 0.0);
  }
  static double stiffness(const PairParameters&, const ContactGeometry&, double) { return 0.0; }
};

/// A tangential spring with history and Coulomb slip (Cundall & Strack 1979, as in LAMMPS):
/// s += v_t dt; F_t = -k_t s - eta_t v_t; if |F_t| > mu F_n, F_t = +-mu F_n and the spring is
/// reset to carry it: s = -(F_t + eta_t v_t) / k_t. `Stiffness` gives k_t.
template <class Stiffness> struct TangentialSpring {
  static constexpr bool has_history = true;
  static constexpr bool uses_r_eff = Stiffness::uses_r_eff;
  static double stiffness(const PairParameters& p, const ContactGeometry& g, double kn) {
    return Stiffness::of(p, g, kn);
  }
  static double force(const PairParameters& p, const ContactGeometry& g, double normal_force,
                      double kn, double& s, double dt) {
    const double kt = Stiffness::of(p, g, kn);
    const double eta = p.tangential_damping * g.m_eff;
    s += g.v_tangent * dt;
    double f = -kt * s - eta * g.v_tangent;
    const double limit = p.friction * normal_force;
    if (std::abs(f) > limit) {
      f = std::copysign(limit, f);
      s = kt > 0.0 ? -(f + eta * g.v_tangent) / kt : 0.0;
    }
    return f;
  }
};

/// Cundall-Strack: k_t = ratio x k_n (linear law) or ratio x tangent stiffness (Hertz).
struct CundallStrackStiffness {
  static constexpr bool uses_r_eff = false;
  static double of(const PairParameters& p, const ContactGeometry&, double kn) {
    return p.tangential_stiffness_ratio * kn;
  }
};
/// Hertz-Mindlin no-slip: k_t = 8 G* sqrt(R* xi).
struct MindlinStiffness {
  static constexpr bool uses_r_eff = true;
  static double of(const PairParameters& p, const ContactGeometry& g, double) {
    return 8.0 * p.effective_shear * std::sqrt(g.r_eff * g.overlap);
  }
};

using CundallStrack = TangentialSpring<CundallStrackStiffness>;
using MindlinNoSlip = TangentialSpring<MindlinStiffness>;

} // namespace talus
