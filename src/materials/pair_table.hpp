#pragma once
// Contact parameters for every pair of materials, mixed once before a run.
#include <cmath>
#include <cstdint>
#include <vector>

#include "materials/material.hpp"

namespace talus {

/// Everything a contact law needs about a pair of materials. Mixing rules (see docs/model.md):
/// moduli by the Hertz and Mindlin series rules; stiffness k_n by the harmonic mean (a material
/// paired with itself keeps its own k_n); restitution, friction and damping by the arithmetic mean.
struct PairParameters {
  double normal_stiffness = 0.0;   ///< k_n, N/m
  double damping_rate = 0.0;       ///< gamma_n, 1/s: eta_n += gamma_n m_eff
  double damping_sqrt_coeff = 0.0; ///< 2 zeta sqrt(k_n): eta_n += this * sqrt(m_eff)
  double tangential_stiffness_ratio = 2.0 / 7.0;
  double tangential_damping = 0.0; ///< gamma_t, 1/s
  double friction = 0.0;           ///< mu
  double effective_young = 0.0;    ///< E*, Pa
  double effective_shear = 0.0;    ///< G*, Pa
  double hertz_damping = 0.0;      ///< A, s
  double restitution = 1.0;        ///< the mixed e (informational for the Hertz law)

  /// Linear dashpot coefficient eta_n (kg/s) for a pair of reduced mass m_eff.
  double normal_dashpot(double m_eff) const {
    const double rate_part = damping_rate * m_eff;
    return damping_sqrt_coeff == 0.0 ? rate_part
                                     : rate_part + damping_sqrt_coeff * std::sqrt(m_eff);
  }
};

PairParameters mix(const Material& a, const Material& b);

class PairTable {
public:
  PairTable() = default;
  explicit PairTable(const std::vector<Material>& materials);

  std::size_t material_count() const { return n_; }
  const PairParameters& operator()(std::uint16_t a, std::uint16_t b) const {
    return table_[a * n_ + b];
  }
  /// The parameters of material a with every material b, indexed by b.
  const PairParameters* row(std::uint16_t a) const { return &table_[a * n_]; }
  /// Replaces the mixed values for one pair (both orders).
  void set(std::uint16_t a, std::uint16_t b, const PairParameters& p);

private:
  std::size_t n_ = 0;
  std::vector<PairParameters> table_;
};

} // namespace talus
