#include "integrate/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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
  template <bool Rotation = true> double operator()(Particles& p, std::size_t i) const {
    auto& g = p.gear;
    const Vec2 displacement = dt * p.velocity[i] + h2 * g.r2[i] + h3 * g.r3[i] + h4 * g.r4[i];
    p.position[i] += displacement;
    p.velocity[i] += dt * g.r2[i] + h2 * g.r3[i] + h3 * g.r4[i];
    g.r2[i] += dt * g.r3[i] + h2 * g.r4[i];
    g.r3[i] += dt * g.r4[i];
    if constexpr (Rotation) {
      p.angle[i] += dt * p.angular_velocity[i] + h2 * g.phi2[i] + h3 * g.phi3[i] + h4 * g.phi4[i];
      p.angular_velocity[i] += dt * g.phi2[i] + h2 * g.phi3[i] + h3 * g.phi4[i];
      g.phi2[i] += dt * g.phi3[i] + h2 * g.phi4[i];
      g.phi3[i] += dt * g.phi4[i];
    }
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
  template <bool Rotation = true> PassReport operator()(Particles& p, std::size_t i) const {
    auto& g = p.gear;
    const Vec2 da = p.force[i] * p.inv_mass[i] - g.r2[i];
    const Vec2 displacement = k0 * da;
    p.position[i] += displacement;
    p.velocity[i] += k1 * da;
    g.r2[i] += da;
    g.r3[i] += k3 * da;
    g.r4[i] += k4 * da;
    if constexpr (Rotation) {
      const double dphi = p.torque[i] * p.inv_inertia[i] - g.phi2[i];
      p.angle[i] += k0 * dphi;
      p.angular_velocity[i] += k1 * dphi;
      g.phi2[i] += dphi;
      g.phi3[i] += k3 * dphi;
      g.phi4[i] += k4 * dphi;
    }
    return {std::isfinite(p.position[i].x + p.position[i].y + p.velocity[i].x + p.velocity[i].y),
            norm2(displacement)};
  }
};

// The angular half of correct_predict_two for particles k and k + 1.
void correct_predict_angles_two(Particles& p, std::size_t k, const GearCorrector& c,
                                const GearPredictor& q) {
  auto& g = p.gear;
  const Lanes inv_inertia = lanes_at(p.inv_inertia.data() + k);
  const Lanes torque = lanes_at(p.torque.data() + k);
  Lanes angle = lanes_at(p.angle.data() + k);
  Lanes spin = lanes_at(p.angular_velocity.data() + k);
  Lanes phi2 = lanes_at(g.phi2.data() + k), phi3 = lanes_at(g.phi3.data() + k);
  Lanes phi4 = lanes_at(g.phi4.data() + k);
  const Lanes dphi = torque * inv_inertia - phi2;
  angle += c.k0 * dphi;
  spin += c.k1 * dphi;
  phi2 += dphi;
  phi3 += c.k3 * dphi;
  phi4 += c.k4 * dphi;
  angle += q.dt * spin + q.h2 * phi2 + q.h3 * phi3 + q.h4 * phi4;
  spin += q.dt * phi2 + q.h2 * phi3 + q.h3 * phi4;
  phi2 += q.dt * phi3 + q.h2 * phi4;
  phi3 += q.dt * phi4;
  store_lanes(p.angle.data() + k, angle);
  store_lanes(p.angular_velocity.data() + k, spin);
  store_lanes(g.phi2.data() + k, phi2);
  store_lanes(g.phi3.data() + k, phi3);
  store_lanes(g.phi4.data() + k, phi4);
}

// GearCorrector, then GearPredictor, for two free particles k and k + 1 side by side, one per
// lane of an SSE2 register (core/lanes.hpp): operation for operation the same arithmetic, so
// the same bits (tests FusedSteps.*, state hashes). Clears a lane of `finite` for a non-finite
// corrected position or velocity; returns the squared displacements of both together.
template <bool Rotation>
Lanes correct_predict_two(Particles& p, std::size_t k, const GearCorrector& c,
                          const GearPredictor& q, LaneMask& finite) {
  auto& g = p.gear;
  // every load before the first store: the stores cannot change what is still to be read
  const Lanes inv_mass = lanes_at(p.inv_mass.data() + k);
  const auto [fx, fy] = components_at(p.force.data() + k);
  const auto [x0, y0] = components_at(p.position.data() + k);
  auto [vx, vy] = components_at(p.velocity.data() + k);
  auto [ax, ay] = components_at(g.r2.data() + k);
  auto [bx, by] = components_at(g.r3.data() + k);
  auto [cx, cy] = components_at(g.r4.data() + k);
  // the correction
  const Lanes dax = inv_mass * fx - ax, day = inv_mass * fy - ay;
  Lanes x = x0 + c.k0 * dax, y = y0 + c.k0 * day;
  vx += c.k1 * dax;
  vy += c.k1 * day;
  ax += dax;
  ay += day;
  bx += c.k3 * dax;
  by += c.k3 * day;
  cx += c.k4 * dax;
  cy += c.k4 * day;
  finite &= magnitude(x + y + vx + vy) <= std::numeric_limits<double>::max();
  // the prediction
  x += q.dt * vx + q.h2 * ax + q.h3 * bx + q.h4 * cx;
  y += q.dt * vy + q.h2 * ay + q.h3 * by + q.h4 * cy;
  vx += q.dt * ax + q.h2 * bx + q.h3 * cx;
  vy += q.dt * ay + q.h2 * by + q.h3 * cy;
  ax += q.dt * bx + q.h2 * cx;
  ay += q.dt * by + q.h2 * cy;
  bx += q.dt * cx;
  by += q.dt * cy;
  if constexpr (Rotation) correct_predict_angles_two(p, k, c, q);
  store_components(p.position.data() + k, x, y);
  store_components(p.velocity.data() + k, vx, vy);
  store_components(g.r2.data() + k, ax, ay);
  store_components(g.r3.data() + k, bx, by);
  store_components(g.r4.data() + k, cx, cy);
  const Lanes dx = x - x0, dy = y - y0;
  return dx * dx + dy * dy;
}

template <bool Rotation> double predict_all(Particles& p, double dt, int threads) {
  const GearPredictor predict(dt);
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  double farthest2 = 0.0;
#pragma omp parallel for schedule(static) num_threads(threads) reduction(max : farthest2)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    if (p.kind[i] == Kind::free)
      farthest2 = std::max(farthest2,
                           predict.template operator()<Rotation>(p, static_cast<std::size_t>(i)));
  return farthest2;
}

template <bool Rotation> PassReport correct_all(Particles& p, double dt, int threads) {
  const GearCorrector correct(dt);
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  bool finite = true;
  double farthest2 = 0.0;
#pragma omp parallel for schedule(static) num_threads(threads) reduction(&& : finite) \
    reduction(max : farthest2)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    if (p.kind[i] == Kind::free) {
      const PassReport s = correct.template operator()<Rotation>(p, static_cast<std::size_t>(i));
      finite = s.finite && finite;
      farthest2 = std::max(farthest2, s.displacement2);
    }
  return {finite, farthest2};
}

template <bool Rotation, bool Gravity>
PassReport correct_predict_all(Particles& p, double dt, Vec2 gravity, int threads) {
  const GearCorrector correct(dt);
  const GearPredictor predict(dt);
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  bool finite = true;
  double farthest2 = 0.0;
  const std::ptrdiff_t pairs = n / 2;
  // two free particles at a time, one per lane; a pair with a wall particle one by one
#pragma omp parallel for schedule(static) num_threads(threads) reduction(&& : finite) \
    reduction(max : farthest2)
  for (std::ptrdiff_t h = 0; h < pairs + n % 2; ++h) {
    const auto k = static_cast<std::size_t>(2 * h);
    if (h < pairs && p.kind[k] == Kind::free && p.kind[k + 1] == Kind::free) {
      LaneMask finite_lanes = {-1, -1};
      const Lanes d2 = correct_predict_two<Rotation>(p, k, correct, predict, finite_lanes);
      finite = finite && finite_lanes[0] != 0 && finite_lanes[1] != 0;
      farthest2 = std::max(farthest2, std::max(d2[0], d2[1]));
      start_forces<Gravity, Rotation>(p, k, gravity, p.force.data(), p.torque.data());
      start_forces<Gravity, Rotation>(p, k + 1, gravity, p.force.data(), p.torque.data());
      continue;
    }
    for (std::size_t i = k; i < std::min(k + 2, static_cast<std::size_t>(n)); ++i) {
      if (p.kind[i] == Kind::free) {
        const Vec2 before = p.position[i];
        finite = correct.template operator()<Rotation>(p, i).finite && finite;
        predict.template operator()<Rotation>(p, i);
        farthest2 = std::max(farthest2, norm2(p.position[i] - before));
      }
      start_forces<Gravity, Rotation>(p, i, gravity, p.force.data(), p.torque.data());
    }
  }
  return {finite, farthest2};
}

} // namespace

double gear_predict(Particles& p, double dt, int threads, bool rotation) {
  return rotation ? predict_all<true>(p, dt, threads) : predict_all<false>(p, dt, threads);
}

PassReport gear_correct(Particles& p, double dt, int threads, bool rotation) {
  return rotation ? correct_all<true>(p, dt, threads) : correct_all<false>(p, dt, threads);
}

PassReport gear_correct_predict(Particles& p, double dt, Vec2 gravity, int threads, bool rotation,
                                bool weight) {
  if (rotation)
    return weight ? correct_predict_all<true, true>(p, dt, gravity, threads)
                  : correct_predict_all<true, false>(p, dt, gravity, threads);
  return weight ? correct_predict_all<false, true>(p, dt, gravity, threads)
                : correct_predict_all<false, false>(p, dt, gravity, threads);
}

} // namespace talus
