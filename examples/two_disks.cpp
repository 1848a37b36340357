// Using the talus C++ API: two disks collide head-on (the thesis' first validation test).
// Build: part of the project (build/examples/example_two_disks).
#include <cstdio>

#include "analysis/observables.hpp"
#include "materials/timestep.hpp"
#include "simulation/simulation.hpp"

int main() {
  using namespace talus;
  World world;
  Material sand;
  sand.name = "sand";
  sand.normal_stiffness = 1.0e4; // N/m
  sand.restitution = 1.0;        // elastic
  sand.friction = 0.0;
  world.materials = {sand};
  world.add_particle({.position = {-0.0011, 0.0}, .radius = 1.0e-3, .velocity = {0.01, 0.0}});
  world.add_particle({.position = {0.0011, 0.0}, .radius = 1.0e-3, .velocity = {-0.01, 0.0}});

  const double m_eff = 0.5 * world.particles.mass[0];
  SimulationConfig config;
  config.timestep = linear_collision_time(1.0e4, 0.0, m_eff) / 50.0;
  config.integrator = Integrator::gear;
  Simulation sim(std::move(world), config);

  const double e0 = energies(sim).total();
  sim.run(5000);
  const auto& p = sim.world().particles;
  std::printf("after %.4f s: v1 = %+.6f m/s, v2 = %+.6f m/s, energy change %.2e (relative)\n",
              sim.time(), p.velocity[0].x, p.velocity[1].x, (energies(sim).total() - e0) / e0);
  return 0;
}
