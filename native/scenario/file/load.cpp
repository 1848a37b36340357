#include "scenario/file/load.hpp"

#include <fmt/format.h>

#include <fstream>
#include <limits>
#include <sstream>

#include "scenario/file/driver_keys.hpp"
#include "scenario/file/picture_request.hpp"
#include "scenario/file/shared_sections.hpp"
#include "scenario/file/simulation_keys.hpp"
#include "scenario/file/stages.hpp"

namespace talus {

namespace {

using keys::inf;

// ---- sections --------------------------------------------------------------------------------

Rect rect(TableReader& r, std::string_view key) {
  const auto v = r.optional_numbers(key);
  if (!v || v->size() != 4 || (*v)[2] <= (*v)[0] || (*v)[3] <= (*v)[1])
    r.fail(key, "expected [x_min, y_min, x_max, y_max] in m with x_max > x_min, y_max > y_min");
  return {{(*v)[0], (*v)[1]}, {(*v)[2], (*v)[3]}};
}

void read_simulation(TableReader& r, SimulationSection& s) {
  if (r.integer("dimension", 2, 2, 3) == 3)
    r.fail("dimension", "3 (spheres) is run by `talus run` alone for now: this command, the Python "
                        "module and the LAMMPS export take 2D scenarios (docs/scenarios.md, "
                        "\"Spheres in 3D\"); allowed here: 2");
  read_clock_and_laws(r, s);
  s.integrator = parse_integrator(r.choice("integrator", "gear", {"gear", "verlet"}));
  s.gravity = r.vec2("gravity", s.gravity);
  s.threads = static_cast<int>(r.integer("threads", s.threads, 0, 1024));
}

// A name thermo.csv's columns (force_NAME_x) and a driver's target can carry.
bool is_group_name(const std::string& name) {
  return !name.empty() && name.find_first_not_of(
                              "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") ==
                              std::string::npos;
}

void read_particles(TableReader& r, ParticlesSection& p, const std::string& file) {
  p.count = static_cast<std::size_t>(r.integer("count", 0, 0, 100'000'000));
  p.shape = r.choice("shape", "sphere", {"disk", "sphere"}) == "disk" ? Shape::disk : Shape::sphere;
  p.material = r.text("material", "");
  if (const toml::table* t = r.table("size")) {
    TableReader sr(*t, file, r.qualified("size"));
    read_size(sr, p.size);
    sr.finish();
  }
  std::size_t k = 0;
  for (const toml::table* t : r.tables("list")) {
    TableReader lr(*t, file, r.qualified("list") + "." + std::to_string(k++));
    ExplicitParticle e;
    e.position = lr.vec2("position", {});
    if (!lr.has("position")) lr.fail_table("position = [x, y] is required");
    e.radius = lr.number("radius", 0.0, 1e-12, inf, "> 0 m");
    if (e.radius <= 0.0) lr.fail_table("radius (> 0 m) is required");
    e.velocity = lr.vec2("velocity", {});
    e.angular_velocity = lr.number("angular_velocity", 0.0, -inf, inf, "any, rad/s");
    e.mass = lr.number("mass", 0.0, 0.0, inf, ">= 0 kg (0: from density)");
    e.kind = lr.choice("kind", "free", {"free", "fixed"});
    e.group = lr.text("group", e.group);
    if (e.kind != "fixed" && lr.has("group"))
      lr.fail("group", "only a fixed grain joins a wall group (this one is free)");
    if (e.group == "walls" || !is_group_name(e.group))
      lr.fail("group", "'" + e.group +
                           "'; allowed: a name of letters, digits and _, other than walls "
                           "(default fixed)");
    e.material = lr.text("material", "");
    lr.finish();
    p.list.push_back(e);
  }
}

void read_packing(TableReader& r, PackingSection& p) {
  p.method = r.choice("method", p.method, {"lattice", "random", "sedimentation"});
  if (r.has("region"))
    p.region = rect(r, "region");
  else
    r.optional_numbers("region");
  p.settle_energy = r.number("settle_energy", p.settle_energy, 0.0, inf, ">= 0");
  p.settle_max_time = r.number("settle_max_time", p.settle_max_time, 0.0, inf, ">= 0 s");
}

void read_geometry(TableReader& r, GeometrySection& g, const std::string& file) {
  g.builder =
      r.choice("builder", g.builder,
               {"none", "box", "silo", "window_box", "hopper", "hourglass", "grain_press", "drum"});
  g.width = r.number("width", g.width, 0.0, inf, ">= 0 m");
  g.height = r.number("height", g.height, 0.0, inf, ">= 0 m");
  g.orifice = r.number("orifice", g.orifice, 0.0, inf, ">= 0 m");
  if (r.has("orifice_x")) g.orifice_x = r.number("orifice_x", 0.0, 0.0, inf, ">= 0 m");
  if (r.has("bin_depth")) g.bin_depth = r.number("bin_depth", 0.0, 0.0, inf, "> 0 m");
  g.gate = r.boolean("gate", false);
  g.wall_angle = r.number("wall_angle", g.wall_angle, 1.0, 89.0,
                          "(1, 89) degrees (a flat floor with an orifice: builder = \"silo\" "
                          "with orifice = WIDTH)");
  // signed, so that a controller (a stage, or Python) can stop the lid or lift it
  g.lid_speed = r.number("lid_speed", g.lid_speed, -inf, inf, "a finite speed in m/s");
  g.radius = r.number("radius", g.radius, 0.0, inf, ">= 0 m");
  g.angular_velocity = r.number("angular_velocity", g.angular_velocity, -inf, inf, "rad/s");
  g.walls = r.choice("walls", g.walls, {"segments", "particles"});
  g.wall_particle_radius = r.number("wall_particle_radius", 0.0, 0.0, inf, ">= 0 m");
  g.wall_material = r.text("wall_material", "");
  g.periodic = r.choice("periodic", g.periodic, {"none", "x", "y", "xy"});
  if (r.has("box"))
    g.box = rect(r, "box");
  else
    r.optional_numbers("box");
  if (g.periodic != "none" && !g.box)
    r.fail("periodic", "a periodic run needs box = [x0, y0, x1, y1]");
  std::size_t k = 0;
  for (const toml::table* t : r.tables("segments")) {
    TableReader sr(*t, file, r.qualified("segments") + "." + std::to_string(k++));
    if (!sr.has("a") || !sr.has("b")) sr.fail_table("a = [x, y] and b = [x, y] are required");
    SegmentSpec seg{sr.vec2("a", {}), sr.vec2("b", {})};
    seg.group = sr.text("group", seg.group);
    // a name thermo.csv's columns (force_NAME_x) and a driver's target can carry; "walls" is
    // every wall's group and "fixed" the fixed grains'
    if (seg.group == "walls" || seg.group == "fixed" || !is_group_name(seg.group))
      sr.fail("group", "'" + seg.group +
                           "'; allowed: a name of letters, digits and _, other than walls and "
                           "fixed (default extra)");
    g.segments.push_back(seg);
    sr.finish();
  }
}

void read_track(TableReader& r, TrackSection& t) {
  for (const double id : r.numbers("ids", 0.0, 4.0e9, "particle ids >= 0"))
    t.ids.push_back(static_cast<std::uint32_t>(id));
  t.select = r.choice("select", t.select, {"none", "largest", "smallest", "nearest", "all"});
  t.at = r.vec2("at", t.at);
  t.count = static_cast<std::size_t>(r.integer("count", 1, 1, 100000));
}

// [[output.stress_regions]]: a name (a word of letters, digits and _, once each) and a region.
void read_stress_regions(TableReader& r, OutputSection& o) {
  const std::vector<const toml::table*> tables = r.tables("stress_regions");
  if (!tables.empty() && !o.stress) r.fail("stress_regions", "needs output.stress = true");
  for (std::size_t k = 0; k < tables.size(); ++k) {
    TableReader t(*tables[k], r.file(), r.qualified("stress_regions") + "." + std::to_string(k));
    StressRegion region;
    std::vector<std::string> taken;
    for (const StressRegion& other : o.stress_regions) taken.push_back(other.name);
    region.name = read_region_name(t, taken);
    if (!t.has("region")) t.fail("region", "missing; expected [x_min, y_min, x_max, y_max] in m");
    region.region = rect(t, "region");
    t.finish();
    o.stress_regions.push_back(std::move(region));
  }
}

void read_output(TableReader& r, OutputSection& o) {
  read_output_intervals(r, o);
  o.track_interval =
      r.number("track_interval", o.track_interval, 0.0, inf, ">= 0 s (0: every step)");
  o.thesis_out = r.boolean("thesis_out", o.thesis_out);
  o.contacts = r.boolean("contacts", o.contacts);
  o.energy_ledger = r.boolean("energy_ledger", o.energy_ledger);
  o.stress = r.boolean("stress", o.stress);
  if (r.has("stress_region")) o.stress_region = rect(r, "stress_region");
  read_stress_regions(r, o);
  o.picture = r.boolean("picture", o.picture);
  o.pictures = r.texts("pictures");
  for (const std::string& p : o.pictures)
    if (const std::string problem = picture_request_problem(p); !problem.empty())
      r.fail("pictures", "'" + p + "': " + problem);
  o.movie = r.boolean("movie", o.movie);
  o.movie_color =
      r.choice("movie_color", o.movie_color, {"speed", "size", "force", "kind", "material"});
  if ((!o.pictures.empty() || o.movie) && o.snapshot_interval <= 0.0)
    r.fail(o.movie ? "movie" : "pictures", "needs snapshots: set output.snapshot_interval > 0");
}

void read_frost(TableReader& r, FrostSection& f) {
  f.model = r.choice("model", f.model, {"none", "uniform", "front"});
  f.heave_factor = r.number("heave_factor", f.heave_factor, 1.0, 100.0, "[1, 100]");
  f.kinetic_threshold = r.number("kinetic_threshold", f.kinetic_threshold, 0.0, inf, ">= 0 J");
  f.min_interval = r.number("min_interval", f.min_interval, 0.0, inf, ">= 0 s");
  f.cycles = static_cast<std::size_t>(r.integer("cycles", 0, 0, 1'000'000));
  f.permafrost_depth = r.number("permafrost_depth", f.permafrost_depth, 0.0, inf, ">= 0 m");
  if (f.model == "front" && !(f.permafrost_depth > 0.0))
    r.fail("permafrost_depth", "the front model needs the depth the front stops at: > 0 m");
  f.heave_strain = r.number("heave_strain", f.heave_strain, 0.0, 1.0, "0 to 1");
  f.conductivity_ratio = r.number("conductivity_ratio", f.conductivity_ratio, 1e-3, 1e3,
                                  "1e-3 to 1e3 (stone / soil; 1: no contrast)");
  f.stone_water = r.number("stone_water", f.stone_water, 0.0, 1e3,
                           "0 to 1e3 (stone / soil latent heat per volume; 0: dry stones)");
  f.ice_content = r.number("ice_content", f.ice_content, 0.0, 1.0,
                           "0 to 1 (ice per volume of frozen fines; 0: their pore fraction)");
  f.crust_length = r.number("crust_length", f.crust_length, 0.0, inf, ">= 0 m (0: column width)");
  f.column_width =
      r.number("column_width", f.column_width, 0.0, inf, ">= 0 m (0: largest stone's diameter)");
  f.stone_radius =
      r.number("stone_radius", f.stone_radius, 0.0, inf, ">= 0 m (0: 1.5 x the median radius)");
  f.freeze_time = r.number("freeze_time", f.freeze_time, 1e-9, inf, "> 0 s");
  f.thaw_time = r.number("thaw_time", f.thaw_time, 1e-9, inf, "> 0 s");
  f.frost_pull = r.boolean("frost_pull", f.frost_pull);
  f.thawed_material = r.text("thawed_material", f.thawed_material);
}

// Reads the table at `name` (if present) with `read`, then rejects any key it did not read.
} // namespace

namespace {

// Where the value at a dotted path was given: its --set, or the file and line.
std::string source_of(const toml::table& root, const std::string& path, const std::string& file) {
  const toml::node_view<const toml::node> node = toml::at_path(root, path);
  if (!node) return file;
  const toml::source_region& r = node.node()->source();
  if (r.path && r.path->starts_with("--set ")) return *r.path;
  return r.begin.line > 0 ? fmt::format("{}:{}", file, r.begin.line) : file;
}

} // namespace

std::uint16_t material_index(const Scenario& s, const std::string& name, const std::string& key) {
  return material_index(s.materials, name, key);
}

namespace {

Scenario load_root(const toml::table& root, const std::string& file, bool check_stages);

// With stages, the run lasts as long as they do unless simulation.duration says; each stage's
// changes, with those before it, must make a scenario that loads (checked here, not when the
// stage starts in the middle of a run).
void settle_stages(Scenario& s, const toml::table& root, const std::string& file,
                   bool check_stages) {
  if (s.stages.empty()) return;
  double before_last = 0.0;
  for (std::size_t k = 0; k + 1 < s.stages.size(); ++k) before_last += s.stages[k].duration;
  const toml::table* sim = root["simulation"].as_table();
  if (!(sim && sim->contains("duration"))) {
    if (!(s.stages.back().duration > 0.0))
      throw ScenarioError(file + ": key 'stages." + std::to_string(s.stages.size() - 1) +
                          ".duration': missing; the last stage needs one, or simulation.duration "
                          "the run's whole length");
    s.simulation.duration = before_last + s.stages.back().duration;
  } // a simulation.duration given may end the run before the later stages start
  if (!check_stages) return;
  // the changes apply to the resolved scenario, as in a run folder: every section is there
  toml::table changed = toml::parse(to_toml(s), file);
  for (std::size_t k = 1; k < s.stages.size(); ++k) {
    try {
      for (const std::string& c : s.stages[k].set) apply_override(changed, c);
      load_root(changed, file, false);
    } catch (const ScenarioError& e) {
      throw ScenarioError("key 'stages." + std::to_string(k) + ".set' (stage '" + s.stages[k].name +
                          "'): " + e.what());
    }
  }
}

Scenario load_root(const toml::table& root, const std::string& file, bool check_stages) {
  Scenario s;
  TableReader top(root, file, "");
  s.name = read_name(top, s.name);
  s.description = top.text("description", "");
  if (const toml::table* t = top.table("simulation")) {
    TableReader r(*t, file, "simulation");
    read_simulation(r, s.simulation);
    r.finish();
  }
  s.materials = read_materials(top, file);
  std::size_t k = 0;
  section(top, "particles", file, [&](TableReader& r) { read_particles(r, s.particles, file); });
  section(top, "packing", file, [&](TableReader& r) { read_packing(r, s.packing); });
  section(top, "geometry", file, [&](TableReader& r) { read_geometry(r, s.geometry, file); });
  k = 0;
  for (const toml::table* t : top.tables("drivers")) {
    TableReader r(*t, file, "drivers." + std::to_string(k++));
    s.drivers.push_back(read_driver(r, s.simulation.impact_speed));
    r.finish();
  }
  section(top, "track", file, [&](TableReader& r) { read_track(r, s.track); });
  section(top, "output", file, [&](TableReader& r) { read_output(r, s.output); });
  section(top, "frost", file, [&](TableReader& r) { read_frost(r, s.frost); });
  s.stages = read_stages(top, file);
  top.finish();
  settle_stages(s, root, file, check_stages);

  // references between sections, each error naming where the reference was given
  const auto check_material = [&](const std::string& name, const std::string& key,
                                  const std::string& path) {
    try {
      material_index(s, name, key);
    } catch (const ScenarioError& e) {
      throw ScenarioError(source_of(root, path, file) + ": " + e.what());
    }
  };
  check_material(s.particles.material, "particles.material", "particles.material");
  check_material(s.geometry.wall_material, "geometry.wall_material", "geometry.wall_material");
  check_material(s.frost.thawed_material, "frost.thawed_material", "frost.thawed_material");
  for (std::size_t i = 0; i < s.particles.list.size(); ++i)
    check_material(s.particles.list[i].material, "particles.list.material",
                   fmt::format("particles.list[{}].material", i));
  const bool tracking = !s.track.ids.empty() || s.track.select != "none";
  for (const std::string& p : s.output.pictures)
    if (parse_picture_request(p).tracks && !tracking)
      throw ScenarioError(file + ": key 'output.pictures': '" + p +
                          "' draws tracks, but [track] selects no particles; set track.ids or "
                          "track.select (largest, smallest, nearest, all)");
  return s;
}

} // namespace

Scenario load_scenario(std::string_view text, const std::string& file,
                       const std::vector<std::string>& overrides) {
  return load_root(parse_with_overrides(text, file, overrides), file, true);
}

Scenario load_scenario_file(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path + ": cannot be read (does it exist?)");
  std::stringstream buf;
  buf << in.rdbuf();
  return load_scenario(buf.str(), path, overrides);
}

} // namespace talus
