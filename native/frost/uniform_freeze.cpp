#include "frost/uniform_freeze.hpp"

#include "talus/frost_heave.hpp"

namespace talus {

double rest_energy_scale(const Simulation& sim) {
  const Particles& p = sim.world().particles;
  double scale = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i)) scale += p.mass[i] * norm(sim.world().gravity) * p.radius[i];
  return scale;
}

void freeze_uniformly(Simulation& sim, double floor, double factor) {
  Particles& p = sim.edit_world().particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i)) p.position[i].y = heaved_height(p.position[i].y, floor, factor);
}

} // namespace talus
