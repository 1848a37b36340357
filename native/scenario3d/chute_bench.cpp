#include "scenario3d/chute_bench.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/random.hpp"
#include "talus/error.hpp"

namespace talus {

Material chute_bench_material() {
  Material m;
  m.density = 1.0;
  m.normal_stiffness = 2.0e5;
  m.tangential_stiffness_ratio = 2.0 / 7.0;
  m.normal_damping_rate = 50.0;
  m.tangential_damping = 0.0;
  m.friction = 0.5;
  return m;
}

ChuteBench build_chute_bench(std::size_t n, std::uint64_t seed) {
  // a periodic side three interaction ranges long at least (sphere_list.hpp): a base of 8 x 4
  require(n >= 1000, "bench chute: " + std::to_string(n) + " spheres; allowed: 1000 or more");
  ChuteBench c;
  c.layers = chute_bench_layers;
  const double per_layer = static_cast<double>(n) / static_cast<double>(c.layers + 1);
  c.ny = static_cast<std::size_t>(std::llround(std::sqrt(0.5 * per_layer)));
  c.nx = 2 * c.ny;
  Scene3& s = c.scene;
  s.materials = {chute_bench_material()};
  const double tilt = 26.0 * std::numbers::pi / 180.0;
  s.gravity = {std::sin(tilt), 0.0, -std::cos(tilt)};
  const double height = static_cast<double>(c.layers) + 1.5;
  s.domain = {{0.0, 0.0, -0.5},
              {static_cast<double>(c.nx), static_cast<double>(c.ny), height},
              {true, true, false}};
  RandomStream rng(seed, 7);
  const auto jitter = [&rng] { return rng.uniform(-0.1, 0.1); };
  for (std::size_t k = 0; k <= c.layers; ++k)
    for (std::size_t j = 0; j < c.ny; ++j)
      for (std::size_t i = 0; i < c.nx; ++i) {
        const Vec3 site{static_cast<double>(i) + 0.5, static_cast<double>(j) + 0.5,
                        static_cast<double>(k) * 1.0};
        if (k == 0) {
          s.add_sphere({.position = site + Vec3{0.0, 0.0, rng.uniform(0.0, 0.1)},
                        .radius = 0.5,
                        .kind = Kind::fixed});
          continue;
        }
        // layers 1 apart, the first 1.1 above the base: no sphere overlaps another at first
        s.add_sphere({.position = site + Vec3{0.0, 0.0, 0.1},
                      .radius = 0.5 * rng.uniform(0.9, 1.0),
                      .velocity = {jitter(), jitter(), jitter()}});
      }
  c.settings.timestep = 1.0e-4;
  c.settings.integrator = Integrator::verlet;
  c.settings.normal_law = law_id<LinearSpringDashpot>;
  c.settings.tangential_law = law_id<CundallStrack>;
  c.settings.skin = 0.1;
  // renumbered every 1000 steps, as LAMMPS sorts its atoms by default (atom_modify sort)
  c.settings.sort_interval = 1000;
  return c;
}

Scene3 tiled_across(const Scene3& scene, std::size_t k) {
  const Domain3& d = scene.domain;
  require(k >= 1, "a tiling takes 1 or more copies along each side");
  require(d.periodic[0] && d.periodic[1] && scene.plates.empty(),
          "only a scene periodic along x and y, without plates, is tiled across them");
  Scene3 out;
  out.materials = scene.materials;
  out.gravity = scene.gravity;
  out.domain = d;
  const Vec3 size = d.size();
  out.domain.hi.x = d.lo.x + static_cast<double>(k) * size.x;
  out.domain.hi.y = d.lo.y + static_cast<double>(k) * size.y;
  const Spheres& s = scene.spheres;
  for (std::size_t ky = 0; ky < k; ++ky)
    for (std::size_t kx = 0; kx < k; ++kx) {
      const Vec3 shift{static_cast<double>(kx) * size.x, static_cast<double>(ky) * size.y, 0.0};
      for (std::size_t i = 0; i < s.size(); ++i) {
        Image3 image{};
        out.add_sphere({.position = d.wrap(s.position[i], image) + shift,
                        .radius = s.radius[i],
                        .material = s.material[i],
                        .kind = s.kind[i],
                        .velocity = s.velocity[i],
                        .angular_velocity = s.angular_velocity[i],
                        .mass = s.mass[i],
                        .inertia = s.inertia[i]});
      }
    }
  return out;
}

} // namespace talus
