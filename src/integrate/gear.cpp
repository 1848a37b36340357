#include "integrate/integrator.hpp"

#include <algorithm>
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

namespace {

// The predictor and the corrector for one particle, shared by the passes below so that a fused
// pass does exactly the arithmetic of the two separate ones.
struct GearPredictor {
  double dt, h2, h3, h4;
  explicit GearPredictor(double step)
      : dt(step), h2(step * step / 2.0), h3(step * step * step / 6.0),
        h4(step * step * step * step / 24.0) {}
  // returns the squared displacement
  double operator()(Particles& p, std::size_t i) const {
    auto& g = p.gear;
    const Vec2 displacement = dt * p.velocity[i] + h2 * g.r2[i] + h3 * g.r3[i] + h4 * g.r4[i];
    p.position[i] += displacement;
    p.velocity[i] += dt * g.r2[i] + h2 * g.r3[i] + h3 * g.r4[i];
    g.r2[i] += dt * g.r3[i] + h2 * g.r4[i];
    g.r3[i] += dt * g.r4[i];
    p.angle[i] += dt * p.angular_velocity[i] + h2 * g.phi2[i] + h3 * g.phi3[i] + h4 * g.phi4[i];
    p.angular_velocity[i] += dt * g.phi2[i] + h2 * g.phi3[i] + h3 * g.phi4[i];
    g.phi2[i] += dt * g.phi3[i] + h2 * g.phi4[i];
    g.phi3[i] += dt * g.phi4[i];
    return norm2(displacement);
  }
};

// r_k += c_k k!/dt^k (dt^2/2) da, with da = F/m - a_predicted.
struct GearCorrector {
  double k0, k1, k3, k4;
  explicit GearCorrector(double dt)
      : k0(gear_c[0] * dt * dt / 2.0), k1(gear_c[1] * dt / 2.0), k3(gear_c[3] * 3.0 / dt),
        k4(gear_c[4] * 12.0 / (dt * dt)) {}
  // whether the corrected position and velocity are finite, and the squared displacement
  StepSeam operator()(Particles& p, std::size_t i) const {
    auto& g = p.gear;
    const Vec2 da = p.force[i] * p.inv_mass[i] - g.r2[i];
    const Vec2 displacement = k0 * da;
    p.position[i] += displacement;
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
    return {std::isfinite(p.position[i].x + p.position[i].y + p.velocity[i].x + p.velocity[i].y),
            norm2(displacement)};
  }
};

} // namespace

double gear_predict(Particles& p, double dt, int threads) {
  const GearPredictor predict(dt);
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  double farthest2 = 0.0;
#pragma omp parallel for schedule(static) num_threads(threads) reduction(max : farthest2)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    if (p.kind[i] == Kind::free)
      farthest2 = std::max(farthest2, predict(p, static_cast<std::size_t>(i)));
  return farthest2;
}

StepSeam gear_correct(Particles& p, double dt, int threads) {
  const GearCorrector correct(dt);
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  bool finite = true;
  double farthest2 = 0.0;
#pragma omp parallel for schedule(static) num_threads(threads) reduction(&& : finite) \
    reduction(max : farthest2)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    if (p.kind[i] == Kind::free) {
      const StepSeam s = correct(p, static_cast<std::size_t>(i));
      finite = s.finite && finite;
      farthest2 = std::max(farthest2, s.displacement2);
    }
  return {finite, farthest2};
}

StepSeam gear_correct_predict(Particles& p, double dt, int threads) {
  const GearCorrector correct(dt);
  const GearPredictor predict(dt);
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  bool finite = true;
  double farthest2 = 0.0;
#pragma omp parallel for schedule(static) num_threads(threads) reduction(&& : finite) \
    reduction(max : farthest2)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    if (p.kind[i] != Kind::free) continue;
    const auto k = static_cast<std::size_t>(i);
    const Vec2 before = p.position[k];
    finite = correct(p, k).finite && finite;
    predict(p, k);
    farthest2 = std::max(farthest2, norm2(p.position[k] - before));
  }
  return {finite, farthest2};
}

} // namespace talus
