#include "engine3d/gear3.hpp"

#include <cstddef>

#include "integrate/integrator.hpp"

namespace talus {

void gear_initialise(GearState3& g, const Spheres& s) {
  const std::size_t n = s.size();
  g.r2.resize(n), g.w2.resize(n);
  g.r3.assign(n, {}), g.r4.assign(n, {}), g.w3.assign(n, {}), g.w4.assign(n, {});
  for (std::size_t i = 0; i < n; ++i) {
    g.r2[i] = s.inv_mass[i] * s.force[i];
    g.w2[i] = s.inv_inertia[i] * s.torque[i];
  }
}

namespace {

template <bool Rotation> void predict(GearState3& g, Spheres& s, double dt, int threads) {
  const double h2 = dt * dt / 2.0, h3 = dt * dt * dt / 6.0, h4 = dt * dt * dt * dt / 24.0;
  const auto n = static_cast<std::ptrdiff_t>(s.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (!s.is_free(i)) continue;
    s.position[i] += dt * s.velocity[i] + h2 * g.r2[i] + h3 * g.r3[i] + h4 * g.r4[i];
    s.velocity[i] += dt * g.r2[i] + h2 * g.r3[i] + h3 * g.r4[i];
    g.r2[i] += dt * g.r3[i] + h2 * g.r4[i];
    g.r3[i] += dt * g.r4[i];
    if constexpr (!Rotation) continue;
    s.angular_velocity[i] += dt * g.w2[i] + h2 * g.w3[i] + h3 * g.w4[i];
    g.w2[i] += dt * g.w3[i] + h2 * g.w4[i];
    g.w3[i] += dt * g.w4[i];
  }
}

template <bool Rotation> void correct(GearState3& g, Spheres& s, double dt, int threads) {
  const double k0 = gear_c[0] * dt * dt / 2.0, k1 = gear_c[1] * dt / 2.0, k3 = gear_c[3] * 3.0 / dt,
               k4 = gear_c[4] * 12.0 / (dt * dt);
  const auto n = static_cast<std::ptrdiff_t>(s.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (!s.is_free(i)) continue;
    const Vec3 da = s.inv_mass[i] * s.force[i] - g.r2[i];
    s.position[i] += k0 * da;
    s.velocity[i] += k1 * da;
    g.r2[i] += da;
    g.r3[i] += k3 * da;
    g.r4[i] += k4 * da;
    if constexpr (!Rotation) continue;
    const Vec3 dw = s.inv_inertia[i] * s.torque[i] - g.w2[i];
    s.angular_velocity[i] += k1 * dw;
    g.w2[i] += dw;
    g.w3[i] += k3 * dw;
    g.w4[i] += k4 * dw;
  }
}

} // namespace

void gear_predict(GearState3& g, Spheres& s, double dt, int threads, bool rotation) {
  rotation ? predict<true>(g, s, dt, threads) : predict<false>(g, s, dt, threads);
}

void gear_correct(GearState3& g, Spheres& s, double dt, int threads, bool rotation) {
  rotation ? correct<true>(g, s, dt, threads) : correct<false>(g, s, dt, threads);
}

} // namespace talus
