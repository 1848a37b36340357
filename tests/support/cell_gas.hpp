#pragma once
// Grains on a jittered lattice in a box periodic in x and y with a cell driver (drivers.hpp,
// Cell): the deforming and sheared cell tests' scene, and the settings they run it with.
#include "core/random.hpp"
#include "simulation/simulation.hpp"

namespace talus::testing {

struct CellGas {
  int per_row = 10;           ///< per_row^2 grains
  double side = 0.3;          ///< m: the box, square, from the origin
  double speed = 0.0;         ///< m/s: the random velocities' spread, each component
  double friction = 0.0;      ///< the material's
  double damping_rate = 50.0; ///< 1/s: the linear law's
  double radius = 0.004;      ///< m: the smallest
  double spread = 0.002;      ///< m: radii from `radius` to this more
  bool flow = false;          ///< with the cell's shear flow, v_x = shear_rate (y - side / 2)
  std::uint64_t seed = 11;
};

/// The scene, with `cell` as its one driver (its Lees-Edwards offset `offset`, m).
inline World cell_gas(const CellGas& g, Cell cell, double offset = 0.0) {
  World w;
  Material m;
  m.density = 2650.0;
  m.normal_stiffness = 1.0e5;
  m.normal_damping_rate = g.damping_rate;
  m.friction = g.friction;
  w.materials = {m};
  w.gravity = {0.0, 0.0};
  w.domain = {{0.0, 0.0}, {g.side, g.side}, true, true};
  w.domain.shear_offset = offset;
  RandomStream rng(g.seed, 1);
  const double pitch = g.side / g.per_row;
  for (int y = 0; y < g.per_row; ++y)
    for (int x = 0; x < g.per_row; ++x) {
      const Vec2 r{pitch * (x + 0.5) + 0.1 * pitch * (rng.uniform() - 0.5),
                   pitch * (y + 0.5) + 0.1 * pitch * (rng.uniform() - 0.5)};
      const double radius = g.radius + g.spread * rng.uniform();
      const double vx =
          (g.flow ? cell.shear_rate * (r.y - 0.5 * g.side) : 0.0) + g.speed * (rng.uniform() - 0.5);
      w.add_particle(
          {.position = r, .radius = radius, .velocity = {vx, g.speed * (rng.uniform() - 0.5)}});
    }
  Driver d;
  d.motion = cell;
  w.drivers.push_back(d);
  return w;
}

/// Its settings: a timestep of 1e-5 s (the contact time is about 2 ms), Cundall-Strack friction
/// or none, `threads` threads however few the grains.
inline SimulationConfig cell_config(double friction, int threads = 1) {
  SimulationConfig c;
  c.timestep = 1e-5;
  c.tangential_law = friction > 0.0 ? law_id<CundallStrack> : law_id<Frictionless>;
  c.threads = threads;
  c.min_particles_per_thread = 1;
  return c;
}

} // namespace talus::testing
