#pragma once
// The neighbour list's pairs by their particles' ids, which a renumbering keeps: for tests that a
// renumbering carries each pair's history along.
#include <algorithm>
#include <cstdint>
#include <tuple>

#include "simulation/simulation.hpp"

namespace talus::testing {

using PairKey = std::tuple<std::uint32_t, std::uint32_t>; // ids, smaller first

/// f(key, entry, from_smaller) for every pair entry of s's list; from_smaller: the entry's first
/// particle has the smaller id.
template <class F> void for_each_pair_by_id(const Simulation& s, F&& f) {
  const NeighbourList& l = s.neighbours();
  const Particles& p = s.world().particles;
  for (std::uint32_t i = 0; i < p.size(); ++i)
    for (std::uint32_t e = l.row_offset[i]; e < l.row_offset[i + 1]; ++e) {
      const std::uint32_t a = p.id[i], b = p.id[l.neighbour[e]];
      f(PairKey{std::min(a, b), std::max(a, b)}, e, a < b);
    }
}

} // namespace talus::testing
