#pragma once
// A material: what a grain or a wall is made of, and the moduli of a pair of materials. SI units
// throughout.
#include <string>

namespace talus {

struct Material {
  std::string name = "default";
  double density = 2650.0;         ///< kg/m^3 (quartz)
  double young = 1.0e8;            ///< Young's modulus E, Pa (Hertzian law)
  double poisson = 0.3;            ///< Poisson ratio nu, in [0, 0.5)
  double restitution = 0.9;        ///< normal restitution e in (0, 1] (linear law)
  double friction = 0.5;           ///< Coulomb friction coefficient mu >= 0
  double tangential_damping = 0.0; ///< gamma_t, 1/s: tangential dashpot eta_t = gamma_t m_eff
  double normal_stiffness = 0.0;   ///< k_n, N/m (linear law; 0 = not given)
  double tangential_stiffness_ratio = -1.0; ///< k_t / k_n (Cundall-Strack); -1: from poisson
  /// gamma_n, 1/s: if >= 0 the linear dashpot is eta_n = gamma_n m_eff (the thesis' eq. 2.10 and
  /// LAMMPS' convention) and `restitution` is ignored by the linear law. Negative: not given.
  double normal_damping_rate = -1.0;
  double hertz_damping = 0.0; ///< A, s: dissipative constant of the viscoelastic Hertz law
  /// A wall that does not deform: a contact with it has the other side's stiffness alone.
  bool rigid = false;
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
