#pragma once
// Normal contact laws: magnitude of the repulsive force from overlap and overlap rate.
// `force` and `stiffness` take one contact (PairParameters, ContactGeometry) or two side by side
// (PairLanes, ContactLanes: contact/contact_lanes.hpp); the same lines serve both.
#include <cmath>

#include "contact/geometry.hpp"
#include "core/lanes.hpp"
#include "materials/pair_table.hpp"

namespace talus {

/// Linear spring-dashpot (thesis eq. 2.10): F_n = k_n xi + eta_n dxi/dt, never attractive.
/// eta_n = gamma_n m_eff, or 2 zeta sqrt(k_n m_eff) from the restitution (materials/timestep.hpp).
struct LinearSpringDashpot {
  static constexpr bool uses_r_eff = false;
  template <class P, class G> static auto force(const P& p, const G& g) {
    return not_below_zero(p.normal_stiffness * g.overlap +
                          p.normal_dashpot(g.m_eff) * g.overlap_rate());
  }
  /// Normal stiffness k_n seen by a tangential spring.
  template <class P, class G> static auto stiffness(const P& p, const G&) {
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
  template <class P, class G> static auto force(const P& p, const G& g) {
    const auto rho = 4.0 / 3.0 * p.effective_young * square_root(g.r_eff);
    const auto s = square_root(g.overlap);
    return not_below_zero(rho * s * (g.overlap + 1.5 * p.hertz_damping * g.overlap_rate()));
  }
  /// Tangent stiffness dF/dxi = 2 E* sqrt(R* xi), used to scale a linear tangential spring.
  template <class P, class G> static auto stiffness(const P& p, const G& g) {
    return 2.0 * p.effective_young * square_root(g.r_eff * g.overlap);
  }
  static double elastic_energy(const PairParameters& p, const ContactGeometry& g) {
    const double rho = 4.0 / 3.0 * p.effective_young * std::sqrt(g.r_eff);
    return 0.4 * rho * g.overlap * g.overlap * std::sqrt(g.overlap);
  }
};

} // namespace talus
