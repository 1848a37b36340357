#pragma once
// The contacts and spring forces of a state by brute force, to check what the neighbour list and
// the force stage found (periodic boxes, deforming and sheared cells).
#include <algorithm>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "simulation/simulation.hpp"

namespace talus::testing {

using IdPairs = std::set<std::pair<std::uint32_t, std::uint32_t>>;

/// The touching pairs: every pair at its nearest periodic image (Domain::minimum_image), by id.
inline IdPairs touching_pairs(const Simulation& s) {
  const Particles& p = s.world().particles;
  const Domain& d = s.world().domain;
  IdPairs out;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      if (norm(d.minimum_image(p.position[i], p.position[j])) < p.radius[i] + p.radius[j])
        out.emplace(std::min(p.id[i], p.id[j]), std::max(p.id[i], p.id[j]));
  return out;
}

/// The touching pairs the simulation's list holds, by id.
inline IdPairs listed_contacts(const Simulation& s) {
  const Particles& p = s.world().particles;
  IdPairs out;
  s.for_each_contact([&](const ContactView& v) {
    out.emplace(std::min(p.id[v.i], p.id[v.j]), std::max(p.id[v.i], p.id[v.j]));
  });
  return out;
}

/// Each grain's force as undamped frictionless linear springs of stiffness k give it: k times
/// the overlap, along the branch, from every grain it touches at the nearest periodic image.
inline std::vector<Vec2> spring_forces(const Simulation& s, double k) {
  const Particles& p = s.world().particles;
  const Domain& d = s.world().domain;
  std::vector<Vec2> f(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < p.size(); ++j) {
      const Vec2 dij = d.minimum_image(p.position[i], p.position[j]);
      const double dist = norm(dij), overlap = p.radius[i] + p.radius[j] - dist;
      if (j != i && overlap > 0.0) f[i] += (k * overlap / dist) * dij;
    }
  return f;
}

} // namespace talus::testing
