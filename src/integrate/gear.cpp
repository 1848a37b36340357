#include "integrate/integrator.hpp"

#include <cmath>

namespace talus {

void gear_initialise(Particles& p) {
  const std::size_t n = p.size();
  auto& g = p.gear;
  g.r2.resize(n);
  g.r3.assign(n, {});
  g.r4.assign(n, {});
  g.phi2.resize(n);
  g.phi3.assign(n, 0.0);
  g.phi4.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    g.r2[i] = p.force[i] * p.inv_mass[i];
    g.phi2[i] = p.torque[i] * p.inv_inertia[i];
  }
}

bool gear_predict(Particles& p, double dt, int threads, const DriftTest& drift) {
  const double h2 = dt * dt / 2.0, h3 = dt * dt * dt / 6.0, h4 = dt * dt * dt * dt / 24.0;
  auto& g = p.gear;
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  const bool has_reference = drift.reference.size() == p.size();
  bool moved = !has_reference;
#pragma omp parallel for schedule(static) num_threads(threads) reduction(|| : moved)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    if (p.kind[i] != Kind::free) continue;
    p.position[i] += dt * p.velocity[i] + h2 * g.r2[i] + h3 * g.r3[i] + h4 * g.r4[i];
    if (has_reference) moved = moved || norm2(p.position[i] - drift.reference[i]) > drift.limit2;
    p.velocity[i] += dt * g.r2[i] + h2 * g.r3[i] + h3 * g.r4[i];
    g.r2[i] += dt * g.r3[i] + h2 * g.r4[i];
    g.r3[i] += dt * g.r4[i];
    p.angle[i] += dt * p.angular_velocity[i] + h2 * g.phi2[i] + h3 * g.phi3[i] + h4 * g.phi4[i];
    p.angular_velocity[i] += dt * g.phi2[i] + h2 * g.phi3[i] + h3 * g.phi4[i];
    g.phi2[i] += dt * g.phi3[i] + h2 * g.phi4[i];
    g.phi3[i] += dt * g.phi4[i];
  }
  return moved;
}

bool gear_correct(Particles& p, double dt, int threads) {
  // r_k += c_k k!/dt^k (dt^2/2) da, with da = F/m - a_predicted.
  const double k0 = gear_c[0] * dt * dt / 2.0;
  const double k1 = gear_c[1] * dt / 2.0;
  const double k3 = gear_c[3] * 3.0 / dt;
  const double k4 = gear_c[4] * 12.0 / (dt * dt);
  auto& g = p.gear;
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  bool finite = true;
#pragma omp parallel for schedule(static) num_threads(threads) reduction(&& : finite)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    if (p.kind[i] != Kind::free) continue;
    const Vec2 da = p.force[i] * p.inv_mass[i] - g.r2[i];
    p.position[i] += k0 * da;
    p.velocity[i] += k1 * da;
    g.r2[i] += da;
    g.r3[i] += k3 * da;
    g.r4[i] += k4 * da;
    const double dphi = p.torque[i] * p.inv_inertia[i] - g.phi2[i];
    p.angle[i] += k0 * dphi;
    p.angular_velocity[i] += k1 * dphi;
    g.phi2[i] += dphi;
    g.phi3[i] += k3 * dphi;
    g.phi4[i] += k4 * dphi;
    finite = finite &&
             std::isfinite(p.position[i].x + p.position[i].y + p.velocity[i].x + p.velocity[i].y);
  }
  return finite;
}

} // namespace talus
