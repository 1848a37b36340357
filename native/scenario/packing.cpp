#include "scenario/packing.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "scenario/file/toml_reader.hpp"

namespace talus {

std::vector<PlacedGrain> lattice_packing(const std::vector<double>& radii, const Rect& region,
                                         RandomStream& rng) {
  std::vector<PlacedGrain> out;
  if (radii.empty()) return out;
  const double r_max = *std::max_element(radii.begin(), radii.end());
  const double pitch = 2.04 * r_max;
  const double width = region.hi.x - region.lo.x, height = region.hi.y - region.lo.y;
  // lattice sites along a length; a count beyond any real packing (a box light-years wide) is
  // cut to one, since converting a larger number to an integer is undefined
  const auto sites = [&](double length) {
    return static_cast<std::size_t>(
        std::clamp(std::floor((length - 2.0 * r_max) / pitch) + 1.0, 0.0, 1.0e15));
  };
  const std::size_t per_row = sites(width), rows = sites(height);
  const bool fits = width >= 2.0 * r_max && height >= 2.0 * r_max;
  const std::size_t capacity =
      fits ? static_cast<std::size_t>(
                 std::min(static_cast<double>(per_row) * static_cast<double>(rows), 1.0e18))
           : 0;
  if (radii.size() > capacity)
    throw ScenarioError("key 'particles.count': " + std::to_string(radii.size()) +
                        " grains do not fit the packing region on a lattice (room for " +
                        std::to_string(capacity) +
                        "); enlarge geometry.height / packing.region or lower the count");
  const double x0 = region.lo.x + 0.5 * (width - pitch * static_cast<double>(per_row - 1));
  for (std::size_t k = 0; k < radii.size(); ++k) {
    const double jitter = 0.01 * r_max * rng.uniform(-1.0, 1.0);
    out.push_back({{x0 + pitch * static_cast<double>(k % per_row) + jitter,
                    region.lo.y + r_max * 1.02 + pitch * static_cast<double>(k / per_row)},
                   radii[k]});
  }
  return out;
}

std::vector<PlacedGrain> random_packing(const std::vector<double>& radii, const Rect& region,
                                        RandomStream& rng) {
  std::vector<PlacedGrain> out;
  for (const double r : radii) {
    bool placed = false;
    for (int attempt = 0; attempt < 100 && !placed; ++attempt) {
      const Vec2 p{rng.uniform(region.lo.x + r, region.hi.x - r),
                   rng.uniform(region.lo.y + r, region.hi.y - r)};
      placed = std::none_of(out.begin(), out.end(), [&](const PlacedGrain& g) {
        return norm2(g.position - p) < (g.radius + r) * (g.radius + r);
      });
      if (placed) out.push_back({p, r});
    }
    if (!placed)
      throw ScenarioError("key 'packing.method': random placement found no room for grain " +
                          std::to_string(out.size()) + " of " + std::to_string(radii.size()) +
                          "; use method = \"lattice\" or a larger region");
  }
  return out;
}

} // namespace talus
