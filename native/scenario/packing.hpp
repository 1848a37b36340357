#pragma once
// Placing grains in a region: on a lattice, or at random without overlaps.
#include <vector>

#include "core/random.hpp"
#include "scenario/scenario.hpp"

namespace talus {

struct PlacedGrain {
  Vec2 position;
  double radius;
};

/// Rows from the bottom of the region, `radii.size()` grains at a pitch of 2.04 r_max, with a
/// small random jitter. Throws ScenarioError if the region holds fewer.
std::vector<PlacedGrain> lattice_packing(const std::vector<double>& radii, const Rect& region,
                                         RandomStream& rng);
/// Random sequential placement without overlaps (100 tries a grain). Throws if one cannot be
/// placed.
std::vector<PlacedGrain> random_packing(const std::vector<double>& radii, const Rect& region,
                                        RandomStream& rng);

} // namespace talus
