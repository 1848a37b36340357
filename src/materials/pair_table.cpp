#include "materials/pair_table.hpp"

#include <cmath>

#include "core/error.hpp"
#include "materials/timestep.hpp"

namespace talus {

PairParameters mix(const Material& a, const Material& b) {
  PairParameters p;
  const auto mean = [](double x, double y) { return 0.5 * (x + y); };
  if (a.normal_stiffness > 0.0 && b.normal_stiffness > 0.0)
    p.normal_stiffness =
        2.0 * a.normal_stiffness * b.normal_stiffness / (a.normal_stiffness + b.normal_stiffness);
  p.restitution = mean(a.restitution, b.restitution);
  if (a.normal_damping_rate >= 0.0 || b.normal_damping_rate >= 0.0) {
    p.damping_rate =
        mean(std::max(a.normal_damping_rate, 0.0), std::max(b.normal_damping_rate, 0.0));
  } else {
    p.damping_sqrt_coeff =
        2.0 * linear_damping_ratio(p.restitution) * std::sqrt(p.normal_stiffness);
  }
  p.tangential_stiffness_ratio = mean(a.tangential_stiffness_ratio, b.tangential_stiffness_ratio);
  p.tangential_damping = mean(a.tangential_damping, b.tangential_damping);
  p.friction = mean(a.friction, b.friction);
  p.effective_young = effective_young(a, b);
  p.effective_shear = effective_shear(a, b);
  p.hertz_damping = mean(a.hertz_damping, b.hertz_damping);
  return p;
}

PairTable::PairTable(const std::vector<Material>& materials) : n_(materials.size()) {
  require(!materials.empty(), "at least one material is needed");
  for (const auto& m : materials) validate(m);
  table_.resize(n_ * n_);
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t j = 0; j < n_; ++j) table_[i * n_ + j] = mix(materials[i], materials[j]);
}

void PairTable::set(std::uint16_t a, std::uint16_t b, const PairParameters& p) {
  require(a < n_ && b < n_, "PairTable::set: material index out of range");
  table_[a * n_ + b] = p;
  table_[b * n_ + a] = p;
}

} // namespace talus
