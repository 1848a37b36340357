#include "scenario3d/build3.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/random.hpp"
#include "materials/pair_table.hpp"
#include "scenario/file/load3.hpp"
#include "scenario/size_distribution.hpp"
#include "scenario3d/box3.hpp"

namespace talus {

namespace {

// Where each sphere goes: a lattice of spacing a over the box, layers from `floor` up.
std::vector<Vec3> lattice_sites(const Scenario3& s, double a, double floor, RandomStream& rng) {
  const Box3Section& g = s.geometry;
  const Vec3 size = g.hi - Vec3{g.lo.x, g.lo.y, floor};
  const auto fit = [&](double length) { return static_cast<std::size_t>(std::floor(length / a)); };
  const std::size_t nx = fit(size.x), ny = fit(size.y), nz = fit(size.z);
  const std::size_t room = nx * ny * nz;
  if (s.particles.count > room) {
    std::ostringstream msg;
    msg << "key 'particles.count': " << s.particles.count
        << " spheres do not fit the box: it holds " << room
        << " on a lattice of spacing 2.2 R_max = " << a
        << " m; allowed: at most that, or a larger geometry.box";
    throw ScenarioError(msg.str());
  }
  std::vector<Vec3> sites;
  for (std::size_t k = 0; k < s.particles.count; ++k) {
    const std::size_t i = k % nx, j = (k / nx) % ny, l = k / (nx * ny);
    const auto nudge = [&] { return 0.05 * a * rng.uniform(-1.0, 1.0); };
    sites.push_back(Vec3{g.lo.x, g.lo.y, floor} +
                    Vec3{a * (0.5 + static_cast<double>(i)) + nudge(),
                         a * (0.5 + static_cast<double>(j)) + nudge(),
                         a * (0.5 + static_cast<double>(l)) + nudge()});
  }
  return sites;
}

// geometry.rough_floor: fixed spheres of the particles' middle radius r on a square lattice of
// spacing about 2r that fits the floor a whole number of times (so a periodic side wraps it
// evenly), each resting on the floor raised by up to r/5 at random (as LAMMPS' chute's base),
// so no free sphere finds a flat gap. Returns the height above which the free spheres start.
double add_rough_floor(const Scenario3& s, Scene3& scene, double r, std::uint16_t material,
                       RandomStream& rng) {
  const Box3Section& g = s.geometry;
  if (!g.rough_floor) return g.lo.z;
  const Vec3 size = g.hi - g.lo;
  const auto count = [&](double length) {
    return std::max<std::size_t>(1, static_cast<std::size_t>(std::floor(length / (2.0 * r))));
  };
  const std::size_t nx = count(size.x), ny = count(size.y);
  const double ax = size.x / static_cast<double>(nx), ay = size.y / static_cast<double>(ny);
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j)
      scene.add_sphere({.position = {g.lo.x + ax * (0.5 + static_cast<double>(i)),
                                     g.lo.y + ay * (0.5 + static_cast<double>(j)),
                                     g.lo.z + r + 0.2 * r * rng.uniform(0.0, 1.0)},
                        .radius = r,
                        .material = material,
                        .kind = Kind::fixed});
  return g.lo.z + 2.4 * r;
}

std::vector<Plane> box_plates(const Box3Section& g, std::uint16_t material) {
  std::vector<Plane> out;
  for (const BoxSide& side : box3_sides(g))
    out.push_back(make_plane(side.point, side.normal, unbounded, unbounded, material));
  return out;
}

// One engine driver a plate of each [[drivers]] target; the loader has checked that the
// targets exist and share no plate.
std::vector<PlateDriver> plate_drivers(const Scenario3& s) {
  std::vector<PlateDriver> out;
  for (const Driver3Section& d : s.drivers)
    for (const std::uint32_t plate : box3_target(s.geometry, d.target)) {
      if (d.servo || d.cell) continue;
      out.push_back({.plate = plate,
                     .motion = d.motion,
                     .velocity = d.velocity,
                     .direction = d.direction,
                     .amplitude = d.amplitude,
                     .frequency = d.frequency,
                     .phase = d.phase,
                     .pivot = d.centre,
                     .angular_velocity = d.angular_velocity});
    }
  return out;
}

// The area of the box's face across a side's normal, m^2: what a servo's stress acts on.
double face_area(const Box3Section& g, const Vec3& normal) {
  const Vec3 size = g.hi - g.lo;
  return std::abs(normal.x) > 0.5   ? size.y * size.z
         : std::abs(normal.y) > 0.5 ? size.x * size.z
                                    : size.x * size.y;
}

// One servo for each servo driver: its plate pressed along the side's inward normal.
std::vector<PlateServo> plate_servos(const Scenario3& s) {
  std::vector<PlateServo> out;
  const std::vector<BoxSide> sides = box3_sides(s.geometry);
  for (const Driver3Section& d : s.drivers) {
    if (!d.servo) continue;
    const std::uint32_t plate = box3_target(s.geometry, d.target).front();
    const Vec3 inward = sides[plate].normal;
    out.push_back({.plate = plate,
                   .direction = inward,
                   .force = d.stress != 0.0 ? d.stress * face_area(s.geometry, inward) : d.force,
                   .max_speed = d.max_speed,
                   .relaxation = d.relaxation});
  }
  return out;
}

// The shortest collision time of the pairs that can meet: two of the smallest spheres, and
// the smallest against the walls.
double shortest_collision_time(const Scene3& scene, const Settings3& c, double r_min,
                               std::uint16_t grain, std::uint16_t wall) {
  const PairTable pairs(scene.materials, c.impact_speed, c.linear_damping);
  const double m = shape_mass(Shape::sphere, r_min, scene.materials[grain].density);
  const auto t_c = [&](std::uint16_t other, double m_eff, double r_eff) {
    return with_normal_law(c.normal_law, [&]<class N>() {
      return N::collision_time(pairs(grain, other), m_eff, r_eff, c.impact_speed);
    });
  };
  double shortest = t_c(grain, 0.5 * m, 0.5 * r_min);
  if (!scene.plates.empty()) shortest = std::min(shortest, t_c(wall, m, r_min));
  return shortest;
}

} // namespace

BuiltScenario3 build_scenario3(const Scenario3& s) {
  BuiltScenario3 out;
  Scene3& scene = out.scene;
  scene.materials = s.materials;
  scene.gravity = s.simulation.gravity;
  scene.domain = {.lo = s.geometry.lo, .hi = s.geometry.hi, .periodic = s.geometry.periodic};
  const std::uint16_t grain = material_index(s, s.particles.material, "particles.material");
  const std::uint16_t wall = material_index(s, s.geometry.wall_material, "geometry.wall_material");
  scene.plates = box_plates(s.geometry, wall);
  scene.drivers = plate_drivers(s);
  scene.servos = plate_servos(s);
  for (const Driver3Section& d : s.drivers)
    if (d.cell)
      scene.cell = CellOf<Vec3>{.strain_rate = d.strain_rate,
                                .pressure = d.pressure,
                                .max_strain_rate = d.max_strain_rate,
                                .relaxation = d.relaxation,
                                .shear_rate = d.shear_rate};
  RandomStream sizes(s.simulation.seed, 1), places(s.simulation.seed, 2);
  const auto [r_min, r_max] = radius_range(s.particles.size);
  RandomStream base(s.simulation.seed, 3);
  const double floor = add_rough_floor(s, scene, 0.5 * (r_min + r_max), grain, base);
  const std::vector<Vec3> sites = lattice_sites(s, 2.2 * r_max, floor, places);
  for (const Vec3& site : sites)
    scene.add_sphere(
        {.position = site, .radius = draw_radius(s.particles.size, sizes), .material = grain});
  const Simulation3Section& sim = s.simulation;
  Settings3& c = out.settings;
  c.normal_law = sim.normal_law;
  c.tangential_law = sim.tangential_law;
  c.integrator = sim.integrator;
  c.verlet_velocity = sim.verlet_velocity;
  c.skin = sim.skin;
  c.threads = sim.threads;
  c.sort_interval = sim.sort_every;
  c.impact_speed = sim.impact_speed;
  c.lever_arm = sim.lever_arm;
  c.linear_damping = sim.linear_damping;
  out.collision_time = shortest_collision_time(scene, c, r_min, grain, wall);
  c.timestep = out.collision_time / sim.timestep_factor;
  if (sim.timestep) {
    if (*sim.timestep > out.collision_time / 5.0) {
      std::ostringstream msg;
      msg << "key 'simulation.timestep': " << *sim.timestep
          << " s resolves the shortest collision (" << out.collision_time
          << " s) in fewer than 5 steps; allowed: <= " << out.collision_time / 5.0
          << " s, or \"auto\" (collision time / " << sim.timestep_factor << ")";
      throw ScenarioError(msg.str());
    }
    c.timestep = *sim.timestep;
  }
  return out;
}

} // namespace talus
