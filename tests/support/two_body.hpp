#pragma once
// Helpers for single-contact tests: two grains (or a grain and a wall) and a run to separation.
#include <cmath>
#include <functional>

#include "analysis/observables.hpp"
#include "simulation/simulation.hpp"

namespace talus::testing {

inline Material elastic_material(double stiffness = 1.0e4) {
  Material m;
  m.name = "test";
  m.density = 2650.0;
  m.normal_stiffness = stiffness;
  m.restitution = 1.0;
  m.friction = 0.0;
  m.young = 1.0e8;
  m.poisson = 0.3;
  return m;
}

/// Two equal grains of radius r, centres 2r + gap apart along `axis` (unit), approaching at
/// relative speed v along the axis, with a sideways offset b (impact parameter) across it.
inline World two_grains(const Material& m, double r, double v, double b = 0.0,
                        Shape shape = Shape::disk, double gap = 0.05) {
  World w;
  w.materials = {m};
  const double sep = 2.0 * r * (1.0 + gap);
  const double dx = std::sqrt(std::max(sep * sep - b * b, 0.0));
  w.add_particle(
      {.position = {-0.5 * dx, -0.5 * b}, .radius = r, .shape = shape, .velocity = {0.5 * v, 0.0}});
  w.add_particle(
      {.position = {0.5 * dx, 0.5 * b}, .radius = r, .shape = shape, .velocity = {-0.5 * v, 0.0}});
  return w;
}

/// Signed overlap of particles 0 and 1 (negative: gap).
inline double overlap01(const Simulation& s) {
  const auto& p = s.world().particles;
  return p.radius[0] + p.radius[1] - norm(p.position[0] - p.position[1]);
}

struct CollisionRecord {
  double contact_time = 0.0; ///< duration of positive overlap, interpolated between steps
  double max_overlap = 0.0;
  double max_force = 0.0;
  bool separated = false;
};

/// Steps until the grains have touched and parted again (or max_steps). `overlap` gives the
/// signed overlap; the start and end of the contact are found by linear interpolation.
inline CollisionRecord collide(Simulation& s, std::uint64_t max_steps,
                               const std::function<double(const Simulation&)>& overlap = overlap01,
                               const std::function<void(const Simulation&)>& each_step = {}) {
  CollisionRecord r;
  double prev = overlap(s), t_start = -1.0;
  const double dt = s.config().timestep;
  for (std::uint64_t k = 0; k < max_steps; ++k) {
    s.step();
    const double now = overlap(s);
    if (each_step) each_step(s);
    r.max_overlap = std::max(r.max_overlap, now);
    r.max_force = std::max(r.max_force, norm(s.world().particles.force[0] -
                                             s.world().particles.mass[0] * s.world().gravity));
    if (prev <= 0.0 && now > 0.0) t_start = s.time() - dt * now / (now - prev);
    if (prev > 0.0 && now <= 0.0 && t_start >= 0.0) {
      r.contact_time = (s.time() - dt * now / (now - prev)) - t_start;
      r.separated = true;
      for (int extra = 0; extra < 3; ++extra) s.step(); // velocities settle after the last kick
      return r;
    }
    prev = now;
  }
  return r;
}

} // namespace talus::testing
