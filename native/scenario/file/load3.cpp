#include "scenario/file/load3.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

#include "scenario/file/load.hpp"
#include "scenario/file/shared_sections.hpp"
#include "scenario/file/simulation_keys.hpp"
#include "scenario3d/box3.hpp"

namespace talus {

namespace {

using keys::inf;

// What 2D scenarios have and the 3D engine does not, with where the engine stands.
constexpr const char* not_in_3d =
    " is not there yet in 3D (simulation.dimension = 3); docs/scenarios.md, \"Spheres in 3D\", "
    "lists what is";

Vec3 vec3(TableReader& r, std::string_view key, Vec3 fallback) {
  if (!r.has(key)) return fallback;
  const std::vector<double> v = r.numbers(key, -inf, inf, "finite numbers");
  if (v.size() != 3) r.fail(key, "expected [x, y, z]");
  return {v[0], v[1], v[2]};
}

// A box of space as [x_min, y_min, z_min, x_max, y_max, z_max].
Region3 region3(TableReader& r, std::string_view key) {
  const std::vector<double> v = r.numbers(key, -inf, inf, "finite numbers");
  if (v.size() != 6 || !(v[3] > v[0] && v[4] > v[1] && v[5] > v[2]))
    r.fail(key, "expected [x_min, y_min, z_min, x_max, y_max, z_max] in m, each max above its "
                "min");
  return {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
}

toml::array region_array(const Region3& b) {
  return toml::array{b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z};
}

void read_simulation(TableReader& r, Simulation3Section& s) {
  r.integer("dimension", 3, 3, 3);
  read_clock_and_laws(r, s);
  s.integrator = parse_integrator(r.choice("integrator", "verlet", {"gear", "verlet"}));
  s.gravity = vec3(r, "gravity", s.gravity);
  s.threads = static_cast<int>(r.integer("threads", s.threads, 0, 1024));
}

void read_particles(TableReader& r, Particles3Section& p, const std::string& file) {
  p.count = static_cast<std::size_t>(r.integer("count", 0, 0, 100'000'000));
  if (r.choice("shape", "sphere", {"disk", "sphere"}) == "disk")
    r.fail("shape", "a 3D scenario's grains are spheres; allowed: sphere");
  p.material = r.text("material", "");
  if (const toml::table* t = r.table("size")) {
    TableReader sr(*t, file, r.qualified("size"));
    read_size(sr, p.size);
    sr.finish();
  }
  if (r.has("list")) r.fail("list", std::string("an explicit list of grains") + not_in_3d);
}

void read_geometry(TableReader& r, Box3Section& g) {
  r.choice("builder", "box", {"box"});
  if (r.has("box")) {
    const Region3 box = region3(r, "box");
    g.lo = box.lo;
    g.hi = box.hi;
  }
  const std::string periodic =
      r.choice("periodic", "none", {"none", "x", "y", "z", "xy", "xz", "yz", "xyz"});
  for (std::size_t k = 0; k < 3; ++k)
    g.periodic[k] = periodic.find(static_cast<char>('x' + k)) != std::string::npos;
  g.open_top = r.boolean("open_top", g.open_top);
  if (g.periodic[2] && r.has("open_top"))
    r.fail("open_top", "a box periodic along z has no top or floor");
  g.rough_floor = r.boolean("rough_floor", g.rough_floor);
  if (g.rough_floor && g.periodic[2])
    r.fail("rough_floor", "a box periodic along z has no floor to glue spheres on");
  g.wall_material = r.text("wall_material", "");
}

// A [[drivers]] entry's keys: its motion's own, the others refused naming the motion that has
// them. Its target is checked against the box by check_targets.
// A cell's keys (as 2D's, scenario/file/driver_keys.cpp, on three axes): a strain rate, or a
// pressure with its fastest rate, and a shear rate; no target (it moves the periodic box).
void read_cell3(TableReader& r, Driver3Section& d) {
  if (r.has("target"))
    r.fail("target", "a cell driver moves the periodic box and every sphere with it: no target");
  d.target = "";
  d.strain_rate = vec3(r, "strain_rate", d.strain_rate);
  d.pressure = r.number("pressure", 0.0, 1e-300, inf, "> 0 Pa");
  d.max_strain_rate = r.number("max_strain_rate", 0.0, 1e-300, inf, "> 0 1/s");
  d.shear_rate = r.number("shear_rate", 0.0, -inf, inf, "1/s");
  d.relaxation = r.number("relaxation", d.relaxation, 1e-9, 1.0, "in (0, 1]");
  if (r.has("strain_rate") && r.has("pressure"))
    r.fail("strain_rate", "a cell takes strain_rate = [x, y, z] (1/s) or pressure (Pa), not both");
  if (!r.has("strain_rate") && !r.has("pressure") && !r.has("shear_rate"))
    r.fail("strain_rate",
           "a cell needs strain_rate = [x, y, z] (1/s), pressure (Pa) or shear_rate (1/s)");
  if (r.has("shear_rate") && d.strain_rate.x != 0.0)
    r.fail("strain_rate", "a sheared cell keeps its width: strain_rate = [0, y, z]");
  if (r.has("pressure") && !r.has("max_strain_rate"))
    r.fail("max_strain_rate", "a cell held at a pressure needs it: its fastest strain rate, 1/s "
                              "(slow enough for the spheres to follow: a quasi-static "
                              "compression)");
  if (!r.has("pressure") && r.has("max_strain_rate"))
    r.fail("max_strain_rate", "only a cell held at a pressure has it");
  if (!r.has("pressure") && r.has("relaxation"))
    r.fail("relaxation", "only a cell held at a pressure has it (or a servo)");
}

Driver3Section read_driver3(TableReader& r, double impact_speed) {
  Driver3Section d;
  const std::string type =
      r.choice("type", "", {"vibrate", "translate", "rotate", "servo", "cell"});
  d.servo = type == "servo";
  d.cell = type == "cell";
  using Motion = PlateDriver::Motion;
  d.motion =
      type == "vibrate" ? Motion::vibrate : (type == "rotate" ? Motion::rotate : Motion::translate);
  d.target = r.text("target", d.target);
  const auto only = [&](std::initializer_list<const char*> names, const char* owner) {
    for (const char* key : names)
      if (type != owner && r.has(key))
        r.fail(key, std::string("only a ") + owner + " driver has it (this one is " + type + ")");
  };
  only({"amplitude", "frequency", "phase", "direction"}, "vibrate");
  only({"velocity"}, "translate");
  only({"centre", "angular_velocity"}, "rotate");
  only({"force", "stress", "max_speed"}, "servo");
  only({"strain_rate", "pressure", "max_strain_rate", "shear_rate"}, "cell");
  if (!d.servo && !d.cell && r.has("relaxation"))
    r.fail("relaxation", "only a servo or cell driver has it (this one is " + type + ")");
  if (d.cell) read_cell3(r, d);
  if (d.servo) {
    if (r.has("force") == r.has("stress"))
      r.fail("force", "a servo needs one target: force (N) or stress (Pa), not both");
    d.force = r.number("force", 0.0, -inf, inf, "N (negative: a pull)");
    d.stress = r.number("stress", 0.0, -inf, inf, "Pa (negative: a pull)");
    d.max_speed = r.number("max_speed", impact_speed, 1e-12, inf, "> 0 m/s");
    d.relaxation = r.number("relaxation", d.relaxation, 1e-9, 1.0, "in (0, 1]");
  }
  d.amplitude = r.number("amplitude", d.amplitude, 0.0, inf, ">= 0 m");
  d.frequency = r.number("frequency", d.frequency, 0.0, inf, ">= 0 Hz");
  d.phase = r.number("phase", d.phase, -inf, inf, "rad");
  d.direction = vec3(r, "direction", d.direction);
  if (norm(d.direction) == 0.0) r.fail("direction", "a vibration's direction must not be zero");
  d.velocity = vec3(r, "velocity", d.velocity);
  d.centre = vec3(r, "centre", d.centre);
  d.angular_velocity = vec3(r, "angular_velocity", d.angular_velocity);
  return d;
}

// Every target a side of this box (or "walls"), and no plate moved by two drivers.
void check_targets(TableReader& top, const Scenario3& s) {
  std::vector<int> driver_of(box3_sides(s.geometry).size(), -1);
  const std::vector<const toml::table*> tables = top.tables("drivers");
  int cell = -1;
  for (std::size_t k = 0; k < s.drivers.size(); ++k) {
    TableReader r(*tables[k], top.file(), "drivers." + std::to_string(k));
    if (s.drivers[k].cell) {
      if (cell >= 0)
        r.fail("type", "drivers." + std::to_string(cell) + " is a cell already; the box has one");
      if (!box3_sides(s.geometry).empty())
        r.fail("type", "a deforming cell needs a box with no plates (they do not follow it): "
                       "geometry.periodic = \"xyz\"");
      cell = static_cast<int>(k);
      continue;
    }
    const std::vector<std::uint32_t> plates = box3_target(s.geometry, s.drivers[k].target);
    if (s.drivers[k].servo && s.drivers[k].target == "walls") {
      std::string sides;
      for (const BoxSide& side : box3_sides(s.geometry))
        sides += (sides.empty() ? "" : ", ") + side.name;
      r.fail("target", "a servo holds one plate at a load; allowed: " + sides);
    }
    if (plates.empty())
      r.fail("target", "'" + s.drivers[k].target +
                           "' is not a plate of this box; allowed: " + box3_targets(s.geometry));
    for (const std::uint32_t w : plates) {
      if (driver_of[w] >= 0)
        r.fail("target", "the " + box3_sides(s.geometry)[w].name + " is moved by drivers." +
                             std::to_string(driver_of[w]) +
                             " already; a plate is moved by one driver at most");
      driver_of[w] = static_cast<int>(k);
    }
  }
}

void read_output(TableReader& r, Output3Section& o) {
  read_output_intervals(r, o);
  o.energy_ledger = r.boolean("energy_ledger", o.energy_ledger);
  o.stress = r.boolean("stress", o.stress);
  if (r.has("stress_region")) {
    if (!o.stress) r.fail("stress_region", "needs output.stress = true");
    o.stress_region = region3(r, "stress_region");
  }
  const std::vector<const toml::table*> tables = r.tables("stress_regions");
  if (!tables.empty() && !o.stress) r.fail("stress_regions", "needs output.stress = true");
  for (std::size_t k = 0; k < tables.size(); ++k) {
    TableReader t(*tables[k], r.file(), r.qualified("stress_regions") + "." + std::to_string(k));
    std::vector<std::string> taken;
    for (const StressRegion3& other : o.stress_regions) taken.push_back(other.name);
    StressRegion3 region{read_region_name(t, taken), {}};
    if (!t.has("region"))
      t.fail("region", "missing; expected [x_min, y_min, z_min, x_max, y_max, z_max] in m");
    region.region = region3(t, "region");
    t.finish();
    o.stress_regions.push_back(std::move(region));
  }
}

Scenario3 load_root(const toml::table& root, const std::string& file) {
  Scenario3 s;
  TableReader top(root, file, "");
  s.name = read_name(top, s.name);
  s.description = top.text("description", "");
  section(top, "simulation", file, [&](TableReader& r) { read_simulation(r, s.simulation); });
  s.materials = read_materials(top, file);
  section(top, "particles", file, [&](TableReader& r) { read_particles(r, s.particles, file); });
  section(top, "geometry", file, [&](TableReader& r) { read_geometry(r, s.geometry); });
  std::size_t k = 0;
  for (const toml::table* t : top.tables("drivers")) {
    TableReader r(*t, file, "drivers." + std::to_string(k++));
    s.drivers.push_back(read_driver3(r, s.simulation.impact_speed));
    r.finish();
  }
  check_targets(top, s);
  section(top, "output", file, [&](TableReader& r) { read_output(r, s.output); });
  if (s.output.energy_ledger &&
      std::ranges::any_of(s.drivers, [](const auto& d) { return d.cell; }))
    top.fail("output.energy_ledger",
             "the ledger has no term yet for the work a deforming cell's strain and sliding "
             "images do; allowed: false with a cell driver");
  for (const char* name : {"packing", "track", "frost", "stages"})
    if (top.has(name)) top.fail(name, std::string("[") + name + "]" + not_in_3d);
  top.finish();
  try {
    material_index(s, s.particles.material, "particles.material");
    material_index(s, s.geometry.wall_material, "geometry.wall_material");
  } catch (const ScenarioError& e) {
    throw ScenarioError(file + ": " + e.what());
  }
  return s;
}

toml::array vec(const Vec3& v) {
  return toml::array{v.x, v.y, v.z};
}

// A driver with its motion's keys alone, as read_driver takes them.
toml::table driver_table(const Driver3Section& d) {
  using Motion = PlateDriver::Motion;
  if (d.cell) {
    toml::table t{{"type", "cell"}};
    if (d.pressure > 0.0) {
      t.insert("pressure", d.pressure);
      t.insert("max_strain_rate", d.max_strain_rate);
      t.insert("relaxation", d.relaxation);
    } else if (d.strain_rate.x != 0.0 || d.strain_rate.y != 0.0 || d.strain_rate.z != 0.0 ||
               d.shear_rate == 0.0) {
      t.insert("strain_rate", vec(d.strain_rate));
    }
    if (d.shear_rate != 0.0) t.insert("shear_rate", d.shear_rate);
    return t;
  }
  if (d.servo) {
    toml::table t{{"type", "servo"},
                  {"target", d.target},
                  {"max_speed", d.max_speed},
                  {"relaxation", d.relaxation}};
    if (d.stress != 0.0)
      t.insert("stress", d.stress);
    else
      t.insert("force", d.force);
    return t;
  }
  switch (d.motion) {
  case Motion::vibrate:
    return toml::table{{"type", "vibrate"},        {"target", d.target},
                       {"amplitude", d.amplitude}, {"frequency", d.frequency},
                       {"phase", d.phase},         {"direction", vec(d.direction)}};
  case Motion::rotate:
    return toml::table{{"type", "rotate"},
                       {"target", d.target},
                       {"centre", vec(d.centre)},
                       {"angular_velocity", vec(d.angular_velocity)}};
  case Motion::translate:
    break;
  }
  return toml::table{{"type", "translate"}, {"target", d.target}, {"velocity", vec(d.velocity)}};
}

toml::table output_table(const Output3Section& o) {
  toml::table out{{"thermo_interval", o.thermo_interval},
                  {"snapshot_interval", o.snapshot_interval},
                  {"checkpoint_interval", o.checkpoint_interval},
                  {"energy_ledger", o.energy_ledger},
                  {"stress", o.stress}};
  if (o.stress_region) out.insert("stress_region", region_array(*o.stress_region));
  if (!o.stress_regions.empty()) {
    toml::array regions;
    for (const StressRegion3& r : o.stress_regions)
      regions.push_back(toml::table{{"name", r.name}, {"region", region_array(r.region)}});
    out.insert("stress_regions", regions);
  }
  return out;
}

} // namespace

std::uint16_t material_index(const Scenario3& s, const std::string& name, const std::string& key) {
  return material_index(s.materials, name, key);
}

Scenario3 load_scenario3(std::string_view text, const std::string& file,
                         const std::vector<std::string>& overrides) {
  return load_root(parse_with_overrides(text, file, overrides), file);
}

std::string to_toml(const Scenario3& s) {
  toml::table sim{{"dimension", 3},
                  {"integrator", to_string(s.simulation.integrator)},
                  {"gravity", vec(s.simulation.gravity)}};
  write_clock_and_laws(sim, s.simulation);
  std::string periodic;
  for (std::size_t k = 0; k < 3; ++k)
    if (s.geometry.periodic[k]) periodic += static_cast<char>('x' + k);
  toml::table geometry{{"builder", "box"},
                       {"box", region_array({s.geometry.lo, s.geometry.hi})},
                       {"periodic", periodic.empty() ? "none" : periodic},
                       {"wall_material", s.geometry.wall_material}};
  if (!s.geometry.periodic[2]) {
    geometry.insert("open_top", s.geometry.open_top);
    geometry.insert("rough_floor", s.geometry.rough_floor);
  }
  toml::table root{
      {"name", s.name},
      {"description", s.description},
      {"simulation", sim},
      {"materials", materials_array(s.materials)},
      {"particles", toml::table{{"count", static_cast<std::int64_t>(s.particles.count)},
                                {"shape", "sphere"},
                                {"material", s.particles.material},
                                {"size", size_table(s.particles.size)}}},
      {"geometry", geometry},
      {"output", output_table(s.output)}};
  if (!s.drivers.empty()) {
    toml::array drivers;
    for (const Driver3Section& d : s.drivers) drivers.push_back(driver_table(d));
    root.insert("drivers", drivers);
  }
  std::ostringstream out;
  out << "# resolved by talus: every key with its value; `talus run` on this file reruns the run\n"
      << root << "\n";
  return with_shortest_floats(out.str());
}

} // namespace talus
