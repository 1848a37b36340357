#include "integrate/integrator.hpp"

#include <string>

#include "core/error.hpp"

namespace talus {

std::string_view to_string(Integrator integrator) {
  return integrator == Integrator::gear ? "gear" : "verlet";
}

Integrator parse_integrator(std::string_view name) {
  if (name == "gear") return Integrator::gear;
  if (name == "verlet") return Integrator::verlet;
  throw InvalidArgument("unknown integrator '" + std::string(name) + "'; allowed: gear, verlet");
}

void verlet_predict(Particles& p, double dt, int threads) {
  const double half = 0.5 * dt;
  const auto n = static_cast<std::ptrdiff_t>(p.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    if (p.kind[i] != Kind::free) continue;
    p.velocity[i] += half * p.inv_mass[i] * p.force[i];
    p.position[i] += dt * p.velocity[i];
    p.angular_velocity[i] += half * p.inv_inertia[i] * p.torque[i];
    p.angle[i] += dt * p.angular_velocity[i];
  }
}

void verlet_correct(Particles& p, double dt, int threads) {
  const double half = 0.5 * dt;
  const auto n = static_cast<std::ptrdiff_t>(p.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    if (p.kind[i] != Kind::free) continue;
    p.velocity[i] += half * p.inv_mass[i] * p.force[i];
    p.angular_velocity[i] += half * p.inv_inertia[i] * p.torque[i];
  }
}

} // namespace talus
