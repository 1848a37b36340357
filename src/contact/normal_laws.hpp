#pragma once
// Normal contact laws: magnitude of the repulsive force from overlap and overlap rate.
#include <algorithm>
#include <cmath>

#include "contact/geometry.hpp"
#include "materials/pair_table.hpp"

namespace talus {

/// Linear spring-dashpot (thesis eq. 2.10): F_n = k_n xi + eta_n dxi/dt, never attractive.
/// eta_n = gamma_n m_eff, or 2 zeta sqrt(k_n m_eff) from the restitution (materials/timestep.hpp).
struct LinearSpringDashpot {
  static constexpr bool uses_r_eff = false;
  static double force(const PairParameters& p, const ContactGeometry& g) {
    const double f = p.normal_stiffness * g.overlap + p.normal_dashpot(g.m_eff) * g.overlap_rate();
    return std::max(f, 0.0);
  }
  /// Normal stiffness k_n seen by a tangential spring.
  static double stiffness(const PairParameters& p, const ContactGeometry&) {
    return p.normal_stiffness;
  }
  static double elastic_energy(const PairParameters& p, const ContactGeometry& g) {
    return 0.5 * p.normal_stiffness * g.overlap * g.overlap;
  }
};

/// Hertzian viscoelastic (Brilliantov et al. 1996; thesis eq. 2.9):
/// F_n = rho (xi^3/2 + 3/2 A sqrt(xi) dxi/dt), rho = 4/3 E* sqrt(R*), never attractive.
struct HertzViscoelastic {
  static constexpr bool uses_r_eff = true;
  static double force(const PairParameters& p, const ContactGeometry& g) {
    const double rho = 4.0 / 3.0 * p.effective_young * std::sqrt(g.r_eff);
    const double s = std::sqrt(g.overlap);
    const double f = rho * s * (g.overlap + 1.5 * p.hertz_damping * g.overlap_rate());
    return std::max(f, 0.0);
  }
  /// Tangent stiffness dF/dxi = 2 E* sqrt(R* xi), used to scale a linear tangential spring.
  static double stiffness(const PairParameters& p, const ContactGeometry& g) {
    return 2.0 * p.effective_young * std::sqrt(g.r_eff * g.overlap);
  }
  static double elastic_energy(const PairParameters& p, const ContactGeometry& g) {
    const double rho = 4.0 / 3.0 * p.effective_young * std::sqrt(g.r_eff);
    return 0.4 * rho * g.overlap * g.overlap * std::sqrt(g.overlap);
  }
};

} // namespace talus
