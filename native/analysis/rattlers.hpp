#pragma once
// Rattlers and the coordination of the load-bearing network (O'Hern et al. 2003, Phys. Rev. E
// 68, 011306): a grain with fewer contacts than it needs to be held in place (d + 1 without
// friction, 3 for disks; with friction d = 2 can hold it) carries no load of the network. Such
// grains are taken out one by one, each time counting only the contacts with the grains still in
// and with walls, until every grain left has enough. The coordination of the grains left is the
// one the isostatic counting (Z = 2d without friction) compares with.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/vec2.hpp"
#include "simulation/simulation.hpp"

namespace talus {

struct LoadBearing {
  std::vector<bool> rattler; ///< per particle: a free grain taken out (false for walls)
  std::size_t grains = 0;    ///< free grains with their centres in the region
  std::size_t rattlers = 0;  ///< of those, rattlers
  double coordination = 0.0; ///< mean contacts of the others in the region (walls included)
};

/// A network's rattlers: partners[i] lists grain i's partners (other grains by index; -1 for what
/// never leaves: a wall, a fixed grain), free[i] whether i may be taken out. Each grain with
/// fewer than `needed` contacts is taken out, its partners losing one, until none is left.
struct Peeled {
  std::vector<bool> rattler; ///< per grain: taken out
  std::vector<int> count;    ///< per free grain: its contacts with what is left
};
Peeled peel_rattlers(const std::vector<std::vector<std::int64_t>>& partners,
                     const std::vector<bool>& free, int needed);

/// The network peeled as peel_rattlers does, with the statistics of the free grains for which
/// in_region(i) holds (disks in 2D, spheres in 3D).
template <class InRegion>
LoadBearing load_bearing_of(const std::vector<std::vector<std::int64_t>>& partners,
                            const std::vector<bool>& free, int needed, InRegion&& in_region) {
  Peeled peeled = peel_rattlers(partners, free, needed);
  LoadBearing out;
  out.rattler = std::move(peeled.rattler);
  double contacts = 0.0;
  for (std::uint32_t i = 0; i < partners.size(); ++i) {
    if (!free[i] || !in_region(i)) continue;
    ++out.grains;
    if (out.rattler[i]) {
      ++out.rattlers;
      continue;
    }
    contacts += peeled.count[i];
  }
  const std::size_t held = out.grains - out.rattlers;
  out.coordination = held > 0 ? contacts / static_cast<double>(held) : 0.0;
  return out;
}

/// The load-bearing network of the free grains, with the statistics of those with their centres
/// in [lo, hi]. `needed`: the contacts a grain needs (3 for frictionless disks, 2 with friction).
LoadBearing load_bearing(const Simulation& sim, Vec2 lo, Vec2 hi, int needed);

/// The contacts a grain needs to be held in place in the run's model: 3 without friction (a
/// frictionless tangential law or every material with friction 0), else 2.
int contacts_needed(const Simulation& sim);

} // namespace talus
