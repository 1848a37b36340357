#include "analysis/rattlers.hpp"

#include <algorithm>

#include "talus/law_table.hpp"

namespace talus {

int contacts_needed(const Simulation& sim) {
  if (sim.config().tangential_law == law_id<Frictionless>) return 3;
  const auto& m = sim.world().materials;
  return std::all_of(m.begin(), m.end(), [](const Material& x) { return x.friction == 0.0; }) ? 3
                                                                                              : 2;
}

Peeled peel_rattlers(const std::vector<std::vector<std::int64_t>>& partners,
                     const std::vector<bool>& free, int needed) {
  Peeled out;
  out.rattler.assign(partners.size(), false);
  out.count.assign(partners.size(), 0);
  std::vector<std::uint32_t> pending;
  for (std::uint32_t i = 0; i < partners.size(); ++i) {
    if (!free[i]) continue;
    out.count[i] = static_cast<int>(partners[i].size());
    if (out.count[i] < needed) pending.push_back(i);
  }
  // take out each grain with too few contacts; its partners lose one and may follow it
  while (!pending.empty()) {
    const std::uint32_t i = pending.back();
    pending.pop_back();
    if (out.rattler[i]) continue;
    out.rattler[i] = true;
    for (const std::int64_t j : partners[i]) {
      if (j < 0 || out.rattler[static_cast<std::size_t>(j)]) continue;
      if (--out.count[static_cast<std::size_t>(j)] < needed)
        pending.push_back(static_cast<std::uint32_t>(j));
    }
  }
  return out;
}

LoadBearing load_bearing(const Simulation& sim, Vec2 lo, Vec2 hi, int needed) {
  const Particles& p = sim.world().particles;
  // each free grain's partners: other free grains by index, walls and wall particles as -1
  std::vector<std::vector<std::int64_t>> partners(p.size());
  sim.for_each_contact([&](const ContactView& v) {
    const bool wall = v.wall >= 0 || !p.is_free(v.j);
    if (p.is_free(v.i)) partners[v.i].push_back(wall ? -1 : static_cast<std::int64_t>(v.j));
    // (signed before the choice: with v.i's unsigned type, -1 would become a huge index)
    if (v.wall < 0 && p.is_free(v.j))
      partners[v.j].push_back(p.is_free(v.i) ? static_cast<std::int64_t>(v.i) : -1);
  });
  std::vector<bool> free(p.size());
  for (std::uint32_t i = 0; i < p.size(); ++i) free[i] = p.is_free(i);
  // a periodic box's grain where it is: wrapped (it may have crossed since the list's build)
  return load_bearing_of(partners, free, needed, [&](std::uint32_t i) {
    return inside_box(sim.world().domain.wrap(p.position[i]), lo, hi);
  });
}

} // namespace talus
