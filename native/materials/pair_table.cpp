#include "materials/pair_table.hpp"

#include <cmath>

#include "materials/timestep.hpp"
#include "talus/error.hpp"

namespace talus {

PairTable::PairTable(const std::vector<Material>& materials, double impact_speed,
                     LinearDamping damping)
    : n_(materials.size()) {
  require(!materials.empty(), "at least one material is needed");
  for (const auto& m : materials) validate(m);
  table_.resize(n_ * n_);
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t j = 0; j < n_; ++j)
      table_[i * n_ + j] = mix(materials[i], materials[j], impact_speed, damping);
}

void PairTable::set(std::uint16_t a, std::uint16_t b, const PairParameters& p) {
  require(a < n_ && b < n_, "PairTable::set: material index out of range");
  table_[a * n_ + b] = p;
  table_[b * n_ + a] = p;
}

} // namespace talus
