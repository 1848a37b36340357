#pragma once
// A material: what a grain or a wall is made of, and the moduli of a pair of materials. SI units
// throughout.
#include <string>

namespace talus {

/// A material. A default-made Material has every key at its default from the key table
/// (material_keys.hpp), the one place where the defaults and the allowed ranges are written.
struct Material {
  std::string name = "default";
  double density;                    ///< kg/m^3
  double young;                      ///< Young's modulus E, Pa (Hertzian law)
  double poisson;                    ///< Poisson ratio nu, in [0, 0.5)
  double restitution;                ///< normal restitution e in (0, 1]
  double friction;                   ///< Coulomb friction coefficient mu >= 0
  double tangential_damping;         ///< gamma_t, 1/s: eta_t = gamma_t m_eff (-1: Tsuji's)
  double normal_stiffness;           ///< k_n, N/m (linear law)
  double tangential_stiffness_ratio; ///< k_t / k_n (Cundall-Strack); -1: from poisson
  /// gamma_n, 1/s: if >= 0 the linear dashpot is eta_n = gamma_n m_eff (the thesis' eq. 2.10 and
  /// LAMMPS' convention) and `restitution` is ignored by the linear law. -1: from restitution.
  double normal_damping_rate;
  double hertz_damping; ///< A, s: dissipative constant of the viscoelastic Hertz law (-1: derived)
  double rolling_friction; ///< mu_r, rolling resistance coefficient (Ai et al. 2011); 0: none
  double rolling_stiffness_factor; ///< k_r = this x k_n mu_r^2 R*^2 (Ai et al.: 2.25)
  double rolling_damping;          ///< eta_r: the rolling dashpot over its critical value
  /// A wall that does not deform: a contact with it has the other side's stiffness alone.
  bool rigid = false;
  /// Every key at its default (material_keys.hpp).
  Material();
};

/// Effective Young's modulus E* of a pair (Hertz): 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2.
inline double effective_young(const Material& a, const Material& b) {
  return 1.0 / ((1.0 - a.poisson * a.poisson) / a.young + (1.0 - b.poisson * b.poisson) / b.young);
}

/// Effective shear modulus G* of a pair (Mindlin): 1/G* = 2(2-nu1)(1+nu1)/E1 + same for 2.
inline double effective_shear(const Material& a, const Material& b) {
  const auto term = [](const Material& m) {
    return 2.0 * (2.0 - m.poisson) * (1.0 + m.poisson) / m.young;
  };
  return 1.0 / (term(a) + term(b));
}

} // namespace talus

// the key table, and with it the default constructor
#include "talus/material_keys.hpp"
