#pragma once
// A small system with every kind of particle and contact, for tests of the engine's bookkeeping
// (renumbering, fused steps): moving grains in a box periodic in x, touching, taken in a random
// order, on a floor of fixed grains and a wall segment, below a row of driven (vibrating) grains.
#include <utility>
#include <vector>

#include "core/random.hpp"
#include "scenario/dense2d.hpp"
#include "simulation/world.hpp"

namespace talus::testing {

// 600 grains of the benchmark's material with friction 0.3 in a 0.3 m x 0.4 m box.
inline World mixed_box() {
  World w;
  Material m = dense2d_material(); // the benchmark's grains
  m.friction = 0.3;
  w.materials = {m};
  w.gravity = {0.0, -9.81};
  w.domain = {{0.0, 0.0}, {0.3, 0.4}, true, false};
  RandomStream rng(5, 1);
  for (int k = 0; k < 30; ++k) // the floor
    w.add_particle({.position = {0.005 + 0.01 * k, 0.005}, .radius = 0.005, .kind = Kind::fixed});
  for (int k = 0; k < 28; ++k) // a driven row at the top
    w.add_particle({.position = {0.01 + 0.01 * k, 0.3}, .radius = 0.005, .kind = Kind::moved});
  // a lattice with jitter, touching, its sites taken in a random order (not a spatial one)
  std::vector<std::pair<int, int>> sites;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 30; ++x) sites.emplace_back(x, y); // across the periodic boundary too
  for (std::size_t k = sites.size(); k > 1; --k)
    std::swap(sites[k - 1],
              sites[static_cast<std::size_t>(rng.uniform() * static_cast<double>(k))]);
  for (const auto& [x, y] : sites)
    w.add_particle({.position = {0.005 + 0.01 * x + 0.0004 * (rng.uniform() - 0.5),
                                 0.015 + 0.0095 * y + 0.0004 * (rng.uniform() - 0.5)},
                    .radius = 0.0045 + 0.001 * rng.uniform(),
                    .velocity = {0.1 * (rng.uniform() - 0.5), 0.1 * (rng.uniform() - 0.5)},
                    .angular_velocity = 5.0 * (rng.uniform() - 0.5)});
  Driver d;
  d.motion = Vibrate{{0.0, 1.0}, 0.001, 20.0, 0.0};
  for (std::uint32_t i = 30; i < 58; ++i) d.targets.particles.push_back(i);
  attach(d, w);
  w.drivers.push_back(d);
  w.add_wall({0.0, 0.002}, {0.3, 0.002}); // a segment floor under the grains too
  return w;
}

} // namespace talus::testing
