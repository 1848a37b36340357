#include "scenario/dense2d.hpp"

#include <numbers>

#include "core/error.hpp"
#include "core/random.hpp"

namespace talus {

Dense2d build_dense2d(std::size_t nx, std::size_t ny, std::uint64_t seed, std::size_t count) {
  require(nx >= 3 && ny >= 1, "dense2d: needs nx >= 3 (periodic in x) and ny >= 1");
  Dense2d d;
  World& w = d.world;
  Material m;
  m.name = "lammps_hooke_history";
  m.density = 1000.0;
  m.normal_stiffness = 1.0e5;
  m.tangential_stiffness_ratio = 2.0 / 7.0;
  m.normal_damping_rate = 100.0;
  m.tangential_damping = 50.0;
  m.friction = 0.5;
  w.materials = {m};
  w.gravity = {0.0, -9.81};
  const double pitch = 0.01, width = pitch * static_cast<double>(nx);
  w.domain = {{0.0, -0.01}, {width, pitch * static_cast<double>(ny) + 0.01}, true, false};
  w.add_wall({-width, 0.0}, {2.0 * width, 0.0}); // beyond the box: its ends are never touched
  RandomStream rng(seed, 3);
  w.particles.reserve(nx * ny);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      if (count > 0 && w.particles.size() == count) break;
      const double r = 0.5 * (0.0085 + 0.001 * rng.uniform());
      const double mass = 4.0 / 3.0 * std::numbers::pi * r * r * r * m.density;
      w.add_particle({.position = {pitch * (static_cast<double>(i) + 0.5),
                                   pitch * (static_cast<double>(j) + 0.5)},
                      .radius = r,
                      .mass = mass,
                      .inertia = 0.5 * mass * r * r});
    }
  d.config.timestep = 1.0e-5;
  d.config.integrator = Integrator::verlet;
  d.config.normal_law = NormalLaw::linear;
  d.config.tangential_law = TangentialLaw::cundall_strack;
  d.config.skin = 1.0e-3;
  return d;
}

} // namespace talus
