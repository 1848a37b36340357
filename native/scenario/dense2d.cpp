#include "scenario/dense2d.hpp"

#include <algorithm>
#include <numbers>

#include "core/random.hpp"
#include "talus/error.hpp"

namespace talus {

Material dense2d_material() {
  Material m;
  m.name = "lammps_hooke_history";
  m.density = 1000.0;
  m.normal_stiffness = 1.0e5;
  m.tangential_stiffness_ratio = 2.0 / 7.0;
  m.normal_damping_rate = 100.0;
  m.tangential_damping = 50.0;
  m.friction = 0.5;
  return m;
}

Material dense2d_thesis_material() {
  Material m = dense2d_material();
  m.name = "thesis_hertz_coulomb";
  m.young = 1.5e9;
  m.poisson = 0.3;
  m.hertz_damping = 2.0e-6;
  return m;
}

void use_thesis_laws(World& world, SimulationConfig& config) {
  for (Material& m : world.materials) m = dense2d_thesis_material();
  config.normal_law = law_id<HertzViscoelastic>;
  config.tangential_law = law_id<ViscousCoulomb>;
}

Dense2d build_dense2d(std::size_t nx, std::size_t ny, std::uint64_t seed, std::size_t count) {
  require(nx >= 3 && ny >= 1, "dense2d: needs nx >= 3 (periodic in x) and ny >= 1");
  Dense2d d;
  World& w = d.world;
  const Material m = dense2d_material();
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
  d.config.normal_law = law_id<LinearSpringDashpot>;
  d.config.tangential_law = law_id<CundallStrack>;
  d.config.skin = 1.0e-3;
  d.config.sort_interval = 1000; // as LAMMPS sorts its atoms (atom_modify sort, default)
  return d;
}

namespace {

template <class T> void repeat(std::vector<T>& v, std::size_t copies) {
  const std::size_t n = v.size();
  v.reserve(n * copies);
  for (std::size_t c = 1; c < copies; ++c) v.insert(v.end(), v.begin(), v.begin() + n);
}

// History of the base pair (a, b) in either order, 0 if the base list has no such pair, or no
// history (a history-free law's list keeps none).
double base_history(const NeighbourList& l, std::uint32_t a, std::uint32_t b) {
  if (l.history.size() != l.neighbour.size()) return 0.0;
  if (a > b) std::swap(a, b);
  const auto first = l.neighbour.begin() + l.row_offset[a];
  const auto last = l.neighbour.begin() + l.row_offset[a + 1];
  const auto at = std::lower_bound(first, last, b);
  return at != last && *at == b ? l.history[at - l.neighbour.begin()] : 0.0;
}

} // namespace

SimulationState tile_dense2d(const SimulationState& base, std::size_t copies, double skin) {
  require(copies >= 1, "tile_dense2d: copies must be >= 1");
  const World& w0 = base.world;
  require(w0.domain.periodic_x && w0.walls.size() == 1 && w0.particles.gear.empty(),
          "tile_dense2d: the base must be a dense2d state (periodic in x, one floor, Verlet)");
  const std::size_t n = w0.particles.size();
  const double width = w0.domain.size().x;
  SimulationState s{w0, {}, base.time, base.steps};
  World& w = s.world;
  Particles& p = w.particles;
  p.for_each_field([&](auto& v) { repeat(v, copies); }); // Gear's are empty: stay so
  for (std::size_t k = 0; k < p.size(); ++k) { // copy c of base particle i: index and id c n + i
    p.position[k].x += width * static_cast<double>(k / n);
    p.id[k] = static_cast<std::uint32_t>(k);
  }
  w.domain.hi.x = w.domain.lo.x + width * static_cast<double>(copies);
  const double wide = w.domain.size().x;
  w.walls[0].a.x = w.domain.lo.x - wide; // the floor reaches beyond the box, as in build_dense2d
  w.walls[0].b.x = w.domain.hi.x + wide;
  build_neighbour_list(s.neighbours, p, w.walls, w.domain, skin);
  NeighbourList& l = s.neighbours;
  const NeighbourList& l0 = base.neighbours;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::uint32_t e = l.row_offset[i]; e < l.row_offset[i + 1]; ++e)
      l.history[e] = base_history(l0, static_cast<std::uint32_t>(i % n),
                                  static_cast<std::uint32_t>(l.neighbour[e] % n));
    for (std::uint32_t e = l.wall_offset[i]; e < l.wall_offset[i + 1]; ++e) {
      const std::size_t a = i % n;
      if (l0.wall_offset[a + 1] > l0.wall_offset[a] &&
          l0.wall_history.size() == l0.wall_segment.size())
        l.wall_history[e] = l0.wall_history[l0.wall_offset[a]];
    }
  }
  return s;
}

} // namespace talus
