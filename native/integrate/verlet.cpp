#include "integrate/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "talus/error.hpp"

namespace talus {

std::string_view to_string(Integrator integrator) {
  return integrator == Integrator::gear ? "gear" : "verlet";
}

Integrator parse_integrator(std::string_view name) {
  if (name == "gear") return Integrator::gear;
  if (name == "verlet") return Integrator::verlet;
  throw InvalidArgument("unknown integrator '" + std::string(name) + "'; allowed: gear, verlet");
}

std::string_view to_string(VerletVelocity v) {
  return v == VerletVelocity::predicted ? "predicted" : "half_step";
}

VerletVelocity parse_verlet_velocity(std::string_view name) {
  if (name == "predicted") return VerletVelocity::predicted;
  if (name == "half_step") return VerletVelocity::half_step;
  throw InvalidArgument("unknown verlet_velocity '" + std::string(name) +
                        "'; allowed: predicted, half_step");
}

// Positions and velocities follow velocity Verlet exactly. The velocity the contact laws see
// while F(t + dt) is computed is, by default, not the half-step one but its prediction
// v(t) + dt a(t) (Groot & Warren 1997, lambda = 1): velocity-dependent damping then lags by
// O(dt^2), not O(dt). VerletVelocity::half_step gives LAMMPS' half-step velocity instead.
double max_stable_timestep(Integrator integrator, double stiffness, double m_eff) {
  require(stiffness > 0.0 && m_eff > 0.0, "max_stable_timestep: stiffness and mass must be > 0");
  const double omega = std::sqrt(stiffness / m_eff);
  return (integrator == Integrator::verlet ? 2.0 : 0.2) / omega;
}

namespace {
template <bool Rotation> double predict_all(Particles& p, double dt, int threads, double lag) {
  const double half = 0.5 * dt;
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  double farthest2 = 0.0;
#pragma omp parallel for schedule(static) num_threads(threads) reduction(max : farthest2)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    farthest2 = std::max(
        farthest2, verlet_predict_one<Rotation>(p, static_cast<std::size_t>(i), dt, half, lag));
  return farthest2;
}
} // namespace

double verlet_predict(Particles& p, double dt, int threads, double lag, bool rotation) {
  p.force_previous.resize(p.size());
  p.torque_previous.resize(p.size());
  const double farthest2 =
      rotation ? predict_all<true>(p, dt, threads, lag) : predict_all<false>(p, dt, threads, lag);
  // F(t) is kept by a swap, not a copy (one pass less over memory): `force` now holds stale
  // values that the force stage overwrites for every particle
  std::swap(p.force, p.force_previous);
  std::swap(p.torque, p.torque_previous);
  return farthest2;
}

bool verlet_correct(Particles& p, double dt, int threads, double lag) {
  const double half = 0.5 * dt;
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  bool finite = true;
#pragma omp parallel for schedule(static) num_threads(threads) reduction(&& : finite)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    finite = verlet_correct_one<true>(p, static_cast<std::size_t>(i), half, lag) && finite;
  return finite;
}

} // namespace talus
