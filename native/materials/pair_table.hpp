#pragma once
// Contact parameters for every pair of materials, mixed once before a run.
#include <cmath>
#include <cstdint>
#include <vector>

#include "materials/material.hpp"
#include "talus/pair_parameters.hpp"

namespace talus {

class PairTable {
public:
  PairTable() = default;
  /// The pairs of `materials`; a Hertz damping left to be derived reaches the restitution at
  /// `impact_speed` (m/s).
  PairTable(const std::vector<Material>& materials, double impact_speed,
            LinearDamping damping = LinearDamping::never_attractive);

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
