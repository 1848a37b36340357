#pragma once
// A hash of a simulation's evolving state, for tests that two runs are the same to the bit.
#include <cstdint>

#include "simulation/simulation.hpp"

namespace talus::testing {

/// FNV-1a over the raw bytes of every evolving field: positions, velocities, spins, forces, the
/// springs of the list's pair and wall contacts, and the box (which a deforming cell changes) with
/// its Lees-Edwards offset.
inline std::uint64_t state_hash(const Simulation& s) {
  std::uint64_t h = 1469598103934665603ULL;
  const auto mix = [&h](const void* data, std::size_t bytes) {
    const auto* c = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < bytes; ++k) h = (h ^ c[k]) * 1099511628211ULL;
  };
  const Particles& p = s.world().particles;
  mix(p.position.data(), p.position.size() * sizeof(Vec2));
  mix(p.velocity.data(), p.velocity.size() * sizeof(Vec2));
  mix(p.angular_velocity.data(), p.angular_velocity.size() * sizeof(double));
  mix(p.force.data(), p.force.size() * sizeof(Vec2));
  mix(s.neighbours().history.data(), s.neighbours().history.size() * sizeof(double));
  mix(s.neighbours().wall_history.data(), s.neighbours().wall_history.size() * sizeof(double));
  const Domain& box = s.world().domain;
  mix(&box.lo, sizeof box.lo);
  mix(&box.hi, sizeof box.hi);
  if (box.sheared()) mix(&box.shear_offset, sizeof box.shear_offset); // Lees-Edwards
  return h;
}

} // namespace talus::testing
