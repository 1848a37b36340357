#include "scenario/build.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "drivers/cell.hpp"
#include "materials/timestep.hpp"
#include "scenario/build_checks.hpp"
#include "scenario/file/load.hpp"
#include "scenario/geometry.hpp"
#include "scenario/packing.hpp"
#include "scenario/sediment.hpp"
#include "scenario/size_distribution.hpp"

namespace talus {

namespace {

std::uint32_t u32(std::size_t v) {
  return static_cast<std::uint32_t>(v);
}

double grain_mass(const Scenario& s, const Material& m, double r) {
  return shape_mass(s.particles.shape, r, m.density);
}

std::vector<Vec2> wall_particle_positions(const SegmentSpec& seg, double spacing) {
  const double length = norm(seg.b - seg.a);
  const auto n = static_cast<std::size_t>(std::ceil(length / spacing));
  std::vector<Vec2> out;
  for (std::size_t k = 0; k <= n; ++k)
    out.push_back(seg.a +
                  (static_cast<double>(k) / static_cast<double>(std::max<std::size_t>(n, 1))) *
                      (seg.b - seg.a));
  return out;
}

} // namespace

Motion motion_of(const DriverSection& d) {
  if (d.type == "vibrate") return Vibrate{d.direction, d.amplitude, d.frequency, d.phase};
  if (d.type == "translate") return Translate{d.velocity};
  if (d.type == "cell")
    return Cell{.strain_rate = d.strain_rate,
                .pressure = d.pressure,
                .max_strain_rate = d.max_strain_rate,
                .relaxation = d.relaxation,
                .shear_rate = d.shear_rate};
  if (d.type == "servo")
    return Servo{.direction = d.direction,
                 .force = d.force,
                 .stress = d.stress,
                 .max_speed = d.max_speed,
                 .relaxation = d.relaxation,
                 .slide_speed = d.slide_speed};
  return Rotate{d.centre, d.angular_velocity};
}

std::vector<DriverSection> all_drivers(const Scenario& s) {
  std::vector<DriverSection> drivers = build_container(s.geometry).drivers;
  drivers.insert(drivers.end(), s.drivers.begin(), s.drivers.end());
  return drivers;
}

std::vector<Material> engine_materials(const Scenario& s) {
  std::vector<Material> materials = s.materials;
  with_normal_law(s.simulation.normal_law, [&]<class N>() {
    for (Material& m : materials) N::resolve_damping(m);
  });
  return materials;
}

std::vector<MeetingPair> meeting_pairs(const World& w) {
  std::set<std::uint16_t> grains, walls;
  const Particles& p = w.particles;
  for (std::size_t i = 0; i < p.size(); ++i) (p.is_free(i) ? grains : walls).insert(p.material[i]);
  for (const Segment& seg : w.walls) walls.insert(seg.material);
  std::vector<MeetingPair> out;
  for (const std::uint16_t a : grains) {
    for (const std::uint16_t b : grains)
      if (b >= a) out.push_back({a, b, false});
    for (const std::uint16_t b : walls) out.push_back({a, b, true});
  }
  return out;
}

double shortest_collision_time(const Scenario& s, const World& w, const PairTable& pairs,
                               double r_min) {
  double shortest = std::numeric_limits<double>::max();
  for (const MeetingPair& m : meeting_pairs(w)) {
    const Material &a = w.materials[m.a], &b = w.materials[m.b];
    const PairParameters& p = pairs(m.a, m.b);
    // against a wall: the grain's own mass and radius (a segment is flat and immovable)
    const double m_eff = m.wall ? grain_mass(s, a, r_min)
                                : 0.5 * std::min(grain_mass(s, a, r_min), grain_mass(s, b, r_min));
    const double r_eff = m.wall ? r_min : 0.5 * r_min;
    const double tc = with_normal_law(s.simulation.normal_law, [&]<class N>() {
      return N::collision_time(p, m_eff, r_eff, s.simulation.impact_speed);
    });
    shortest = std::min(shortest, tc);
  }
  return shortest;
}

namespace {

// The integrator's stability bound for the stiffest oscillation of the pairs that can meet, for
// the lightest grain (the bound is then conservative): the normal one (linear k_n, or Hertz'
// tangent stiffness at the impact speed), or a tangential spring's, which also turns the grains
// and so oscillates faster than its stiffness alone says: k_t (1 + m r^2 / I) / m_eff.
double stable_timestep_bound(const Scenario& s, const World& w, const PairTable& pairs_of,
                             const SimulationConfig& c, double r_min) {
  double k_max = 0.0, m_min = std::numeric_limits<double>::max();
  const auto pairs = meeting_pairs(w);
  for (const MeetingPair& m : pairs)
    m_min = std::min(m_min, 0.5 * grain_mass(s, w.materials[m.a], r_min));
  const double turning = 1.0 + 1.0 / shape_inertia(s.particles.shape, 1.0, 1.0);
  for (const MeetingPair& m : pairs) {
    const PairParameters& p = pairs_of(m.a, m.b);
    const double m_eff = m.wall ? 2.0 * m_min : m_min;
    ContactGeometry g;
    g.m_eff = m_eff;
    g.r_eff = m.wall ? r_min : 0.5 * r_min;
    const double v = s.simulation.impact_speed;
    const double k = with_normal_law(c.normal_law, [&]<class N>() {
      g.overlap = N::peak_overlap(p, m_eff, g.r_eff, v);
      return N::peak_stiffness(p, m_eff, g.r_eff, v);
    });
    const double kt =
        with_tangential_law(c.tangential_law, [&]<class T>() { return T::stiffness(p, g, k); });
    k_max = std::max({k_max, k, turning * kt});
  }
  return max_stable_timestep(c.integrator, k_max, m_min);
}

} // namespace

double chosen_timestep(const Scenario& s, const World& w, const PairTable& pairs,
                       const SimulationConfig& c, double r_min, double collision_time) {
  const double automatic = collision_time / s.simulation.timestep_factor;
  if (!s.simulation.timestep) return automatic;
  const double bound = stable_timestep_bound(s, w, pairs, c, r_min);
  if (*s.simulation.timestep > bound) {
    std::ostringstream msg;
    msg << "key 'simulation.timestep': " << *s.simulation.timestep
        << " s is above the stability bound " << bound << " s of the " << to_string(c.integrator)
        << " integrator for the stiffest contact (collision time " << collision_time
        << " s); allowed: <= " << bound << " s, or \"auto\" (collision time / "
        << s.simulation.timestep_factor << " = " << automatic << " s)";
    throw ScenarioError(msg.str());
  }
  return *s.simulation.timestep;
}

namespace {

// The grains' radii, drawn first: they set the wall particle radius and the timestep.
struct GrainSizes {
  std::vector<double> radii; ///< of the counted grains
  double r_min = 0.0;        ///< of every free grain, counted or listed
};

GrainSizes draw_grain_sizes(const Scenario& s, RandomStream& rng) {
  GrainSizes g;
  g.radii.resize(s.particles.count);
  for (double& r : g.radii) r = draw_radius(s.particles.size, rng);
  g.r_min = std::numeric_limits<double>::max();
  for (const double r : g.radii) g.r_min = std::min(g.r_min, r);
  for (const ExplicitParticle& e : s.particles.list)
    if (e.kind == "free") g.r_min = std::min(g.r_min, e.radius);
  if (g.radii.size() + s.particles.list.size() == 0)
    throw ScenarioError("key 'particles.count': a scenario needs grains (count > 0 or a list)");
  if (g.r_min == std::numeric_limits<double>::max()) // every grain listed, none of them free
    throw ScenarioError(
        "key 'particles.list': every grain's kind is \"fixed\" or \"moved\", so nothing can "
        "move under the contact forces and no timestep fits them; give one a kind = \"free\", or "
        "particles.count > 0");
  // the sizes a grain can have (not only those drawn this time) decide what a gap lets through
  double r_small = std::numeric_limits<double>::max(), r_large = 0.0;
  if (s.particles.count > 0) std::tie(r_small, r_large) = radius_range(s.particles.size);
  for (const ExplicitParticle& e : s.particles.list)
    if (e.kind == "free")
      r_small = std::min(r_small, e.radius), r_large = std::max(r_large, e.radius);
  check_wall_gaps(s, r_small, r_large);
  return g;
}

// The container's walls into out.world, by group (out.groups): segments, or wall particles a
// radius apart, overlapping so that no grain can pass between them. A driven group's wall
// particles are moved by their driver, the others fixed.
void build_walls(const Scenario& s, const ContainerShape& shape,
                 const std::vector<DriverSection>& drivers, double r_wall, std::uint16_t wall_mat,
                 BuiltScenario& out) {
  World& w = out.world;
  const bool particle_walls = s.geometry.walls == "particles";
  const auto driven = [&](const std::string& group) {
    return std::any_of(drivers.begin(), drivers.end(), [&](const DriverSection& d) {
      return d.target == group || d.target == "walls";
    });
  };
  for (const auto& [group, segments] : shape.groups) {
    if (group == "walls") continue; // the union, filled below from the members
    for (const SegmentSpec& seg : segments) {
      DriverTargets& own = out.groups[group];
      DriverTargets& all = out.groups["walls"];
      if (!particle_walls) {
        const auto k = u32(w.add_wall(seg.a, seg.b, wall_mat));
        own.segments.push_back(k);
        all.segments.push_back(k);
        continue;
      }
      for (const Vec2 p : wall_particle_positions(seg, r_wall)) {
        const auto k = u32(w.add_particle({.position = p,
                                           .radius = r_wall,
                                           .material = wall_mat,
                                           .kind = driven(group) ? Kind::moved : Kind::fixed}));
        own.particles.push_back(k);
        all.particles.push_back(k);
      }
    }
  }
}

void set_periodic_domain(const Scenario& s, Domain& d) {
  if (s.geometry.periodic == "none") return;
  d.lo = s.geometry.box->lo;
  d.hi = s.geometry.box->hi;
  d.periodic_x = s.geometry.periodic.find('x') != std::string::npos;
  d.periodic_y = s.geometry.periodic.find('y') != std::string::npos;
}

// The grains: the explicit list, then the counted ones (radii) placed in out.fill.
void place_grains(const Scenario& s, const std::vector<double>& radii, RandomStream& rng,
                  BuiltScenario& out) {
  World& w = out.world;
  check_listed_grains_clear_of_walls(s, w, out.bounds);
  for (const ExplicitParticle& e : s.particles.list) {
    // fixed grains are a wall group ("fixed" unless named): their force in thermo.csv, a driver
    if (e.kind == "fixed") out.groups[e.group].particles.push_back(u32(w.particles.size()));
    w.add_particle({.position = e.position,
                    .radius = e.radius,
                    .material = material_index(s, e.material, "particles.list.material"),
                    .kind = e.kind == "fixed" ? Kind::fixed : Kind::free,
                    .shape = s.particles.shape,
                    .velocity = e.velocity,
                    .angular_velocity = e.angular_velocity,
                    .mass = e.mass});
  }
  if (radii.empty()) return;
  if (!(out.fill.hi.x > out.fill.lo.x && out.fill.hi.y > out.fill.lo.y))
    throw ScenarioError("key 'packing.region': no region to place grains in; give a geometry "
                        "builder or packing.region = [x0, y0, x1, y1]");
  // explicit grains inside the region keep their room: the lattice starts above them
  Rect region = out.fill;
  for (const ExplicitParticle& e : s.particles.list)
    if (e.position.x > region.lo.x && e.position.x < region.hi.x && e.position.y < region.hi.y)
      region.lo.y = std::max(region.lo.y, e.position.y + e.radius);
  const auto placed = s.packing.method == "random" ? random_packing(radii, region, rng)
                                                   : lattice_packing(radii, region, rng);
  const std::uint16_t grain_mat = material_index(s, s.particles.material, "particles.material");
  for (const PlacedGrain& g : placed)
    w.add_particle({.position = g.position,
                    .radius = g.radius,
                    .material = grain_mat,
                    .shape = s.particles.shape});
}

// The simulation's settings, its timestep (the collision time's fraction, or one given within
// the stability bound) and the stability guard's box: the container and as much again around it.
void configure(const Scenario& s, double r_min, BuiltScenario& out) {
  out.pairs =
      PairTable(out.world.materials, s.simulation.impact_speed, s.simulation.linear_damping);
  out.collision_time = shortest_collision_time(s, out.world, out.pairs, r_min);
  SimulationConfig& c = out.config;
  c.integrator = s.simulation.integrator;
  c.verlet_velocity = s.simulation.verlet_velocity;
  c.lever_arm = s.simulation.lever_arm;
  c.linear_damping = s.simulation.linear_damping;
  c.normal_law = s.simulation.normal_law;
  c.tangential_law = s.simulation.tangential_law;
  c.threads = s.simulation.threads;
  c.skin = s.simulation.skin;
  c.impact_speed = s.simulation.impact_speed;
  // the frost models keep per-particle state of their own by index: no renumbering under them
  c.sort_interval = s.frost.model == "none" ? s.simulation.sort_every : 0;
  c.timestep = chosen_timestep(s, out.world, out.pairs, c, r_min, out.collision_time);
  check_step_count(s, c.timestep);
  const Rect& b = out.bounds;
  if (b.hi.x > b.lo.x && b.hi.y > b.lo.y) {
    const Vec2 size = b.hi - b.lo;
    c.escape_lo = b.lo - size;
    c.escape_hi = b.hi + size;
  }
}

// The wall groups the stages' conditions name are the geometry's.
void check_stage_groups(const Scenario& s, const BuiltScenario& out) {
  for (std::size_t k = 0; k < s.stages.size(); ++k) {
    if (s.stages[k].group.empty() || out.groups.count(s.stages[k].group)) continue;
    std::string names;
    for (const auto& [name, _] : out.groups) names += (names.empty() ? "" : ", ") + name;
    throw ScenarioError("key 'stages." + std::to_string(k) + ".group': no wall group '" +
                        s.stages[k].group + "' in this geometry; groups: " + names);
  }
}

// output.stress needs an area: its region, or the container's extent.
void check_stress_region(const Scenario& s, const BuiltScenario& out) {
  const Rect& b = out.bounds;
  if (!s.output.stress || s.output.stress_region || (b.hi.x > b.lo.x && b.hi.y > b.lo.y)) return;
  throw ScenarioError("key 'output.stress_region': needed with output.stress = true where the "
                      "geometry has no extent (builder \"none\" without walls); expected [x_min, "
                      "y_min, x_max, y_max] in m");
}

// Each driver sets its walls' positions from its own origins: a wall two drivers move would
// follow the last one alone, whatever the first asked. Refused, naming both.
void check_one_driver_each(const std::vector<DriverSection>& drivers, const BuiltScenario& out) {
  std::map<std::uint32_t, std::string> particle, segment; // wall -> the group that drives it
  for (const DriverSection& d : drivers) {
    if (d.type == "cell") continue;
    const DriverTargets& t = out.groups.at(d.target);
    const auto claim = [&](std::map<std::uint32_t, std::string>& owner, std::uint32_t k) {
      const auto [at, fresh] = owner.emplace(k, d.target);
      if (fresh) return;
      throw ScenarioError(
          "key 'drivers.target': the group '" + d.target + "' shares walls with '" + at->second +
          "', which another driver moves (" +
          (d.target == at->second ? "the same group twice" : "a group within the other") +
          ", or a geometry's own driver such as the grain press's lid or the drum's turn): a "
          "wall follows one driver; give each wall group one");
    };
    for (const auto i : t.particles) claim(particle, i);
    for (const auto k : t.segments) claim(segment, k);
  }
}

// The deforming periodic cell: attached to the box (it has no target).
void add_cell_driver(const DriverSection& d, BuiltScenario& out) {
  Driver driver;
  driver.motion = motion_of(d);
  try {
    attach(driver, out.world);
  } catch (const InvalidArgument& e) {
    throw ScenarioError(std::string("drivers (type \"cell\"): ") + e.what());
  }
  out.world.drivers.push_back(std::move(driver));
}

void add_drivers(const std::vector<DriverSection>& drivers, BuiltScenario& out) {
  for (const DriverSection& d : drivers)
    if (d.type != "cell" && !out.groups.contains(d.target)) {
      std::string names;
      for (const auto& [name, _] : out.groups) names += (names.empty() ? "" : ", ") + name;
      throw ScenarioError("key 'drivers.target': no wall group '" + d.target +
                          "' in this geometry; groups: " + names);
    }
  check_one_driver_each(drivers, out);
  for (const DriverSection& d : drivers) {
    if (d.type == "cell") {
      add_cell_driver(d, out);
      continue;
    }
    const auto group = out.groups.find(d.target);
    // fixed grains a driver moves are moved grains (the container's wall particles are made so)
    for (const std::uint32_t i : group->second.particles)
      if (out.world.particles.kind[i] == Kind::fixed) out.world.particles.kind[i] = Kind::moved;
    Driver driver;
    driver.targets = group->second;
    driver.motion = motion_of(d);
    try { // the checks the engine makes as it starts, made here with the key to name
      attach(driver, out.world);
    } catch (const InvalidArgument& e) {
      throw ScenarioError("drivers (target '" + d.target + "'): " + e.what());
    }
    out.world.drivers.push_back(std::move(driver));
  }
  try { // the engine's own check, made here with the key to name
    require_cell_fits(out.world);
  } catch (const InvalidArgument& e) {
    throw ScenarioError(std::string("drivers (type \"cell\"): ") + e.what());
  }
}

// The tracked particles: those listed by id, then those the selection picks (each once).
void select_tracked(const Scenario& s, BuiltScenario& out) {
  const Particles& p = out.world.particles;
  for (const auto id : s.track.ids) {
    if (id >= p.size())
      throw ScenarioError("key 'track.ids': particle id " + std::to_string(id) +
                          " does not exist (" + std::to_string(p.size()) + " particles)");
    out.tracked.push_back(id);
  }
  if (s.track.select == "none") return;
  std::vector<std::uint32_t> free;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i)) free.push_back(u32(i));
  const auto key = [&](std::uint32_t i) {
    if (s.track.select == "largest") return -p.radius[i];
    if (s.track.select == "smallest") return p.radius[i];
    return norm2(p.position[i] - s.track.at);
  };
  if (s.track.select != "all") // "all": every grain, in id order
    std::stable_sort(free.begin(), free.end(), [&](auto a, auto b) { return key(a) < key(b); });
  const std::size_t n =
      s.track.select == "all" ? free.size() : std::min(s.track.count, free.size());
  for (std::size_t k = 0; k < n; ++k)
    if (std::find(out.tracked.begin(), out.tracked.end(), free[k]) == out.tracked.end())
      out.tracked.push_back(free[k]); // a particle listed in ids too is tracked once
}

} // namespace

BuiltScenario build_scenario(const Scenario& s, const SettleProgress& progress) {
  BuiltScenario out;
  World& w = out.world;
  w.materials = engine_materials(s);
  w.gravity = s.simulation.gravity;
  RandomStream rng(s.simulation.seed, 1);

  check_memory(s.particles.count + s.particles.list.size());
  check_start_overlaps(s);
  const GrainSizes sizes = draw_grain_sizes(s, rng);

  const ContainerShape shape = build_container(s.geometry);
  const bool particle_walls = s.geometry.walls == "particles";
  const double r_wall =
      s.geometry.wall_particle_radius > 0.0 ? s.geometry.wall_particle_radius : sizes.r_min;
  out.fill = s.packing.region.value_or(shape.fill);
  if (particle_walls && !s.packing.region) { // wall particles reach r_wall into the container
    out.fill.lo += Vec2{r_wall, r_wall};
    out.fill.hi -= Vec2{r_wall, r_wall};
  }
  out.bounds = shape.bounds;
  check_position_resolution(s, out.bounds, out.fill, sizes.r_min);
  const std::uint16_t wall_mat =
      material_index(s, s.geometry.wall_material, "geometry.wall_material");
  std::vector<DriverSection> drivers = shape.drivers;
  drivers.insert(drivers.end(), s.drivers.begin(), s.drivers.end());
  build_walls(s, shape, drivers, r_wall, wall_mat, out);
  // segment ends a rounding step apart (polylines made by a script) are one joint
  join_segment_ends(w.walls, wall_joint_tolerance * sizes.r_min);
  set_periodic_domain(s, w.domain);

  place_grains(s, sizes.radii, rng, out);
  check_stage_groups(s, out);
  check_stress_region(s, out);
  configure(s, sizes.r_min, out);
  if (s.packing.method == "sedimentation" && !sizes.radii.empty())
    sediment(s, shape.gate, wall_mat, wall_joint_tolerance * sizes.r_min, progress, out);
  // frost holds grains in place, and held grains would not follow a deforming cell
  if (s.frost.model != "none" &&
      std::any_of(drivers.begin(), drivers.end(), [](const auto& d) { return d.type == "cell"; }))
    throw ScenarioError("drivers (type \"cell\"): a frost model holds grains, which would not "
                        "follow the cell; allowed with a cell: frost.model = \"none\"");
  add_drivers(drivers, out);
  select_tracked(s, out);
  return out;
}

} // namespace talus
