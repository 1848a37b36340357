#include "scenario/file/load.hpp"

#include <fmt/format.h>

#include <fstream>
#include <limits>
#include <sstream>

#include "scenario/file/driver_keys.hpp"
#include "scenario/file/picture_request.hpp"
#include "scenario/file/stages.hpp"
#include "talus/material_keys.hpp"

namespace talus {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// ---- --set overrides -------------------------------------------------------------------------

toml::node* child(toml::node& parent, const std::string& part, bool create,
                  const std::string& key) {
  if (auto* t = parent.as_table()) {
    if (!t->contains(part)) {
      if (!create) return nullptr;
      t->insert(part, toml::table{});
    }
    return t->get(part);
  }
  if (auto* a = parent.as_array()) {
    std::size_t idx = 0;
    try {
      idx = std::stoul(part);
    } catch (...) {
      throw ScenarioError("--set " + key + ": '" + part + "' must be an index into an array");
    }
    if (idx >= a->size())
      throw ScenarioError("--set " + key + ": index " + part + " is past the end of the array (" +
                          std::to_string(a->size()) + " entries)");
    return a->get(idx);
  }
  throw ScenarioError("--set " + key + ": '" + part + "' is inside a value, not a table");
}

void apply_override(toml::table& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw ScenarioError("--set '" + assignment +
                        "': expected key=value, e.g. particles.count=5000");
  const std::string key = assignment.substr(0, eq), value = assignment.substr(eq + 1);
  // dotted parts; an array index may also be written in brackets: materials[0].friction is
  // materials.0.friction
  std::vector<std::string> parts;
  std::stringstream in(key);
  for (std::string p; std::getline(in, p, '.');) {
    std::size_t open = p.find('[');
    parts.push_back(p.substr(0, open));
    while (open != std::string::npos) {
      const std::size_t close = p.find(']', open);
      if (close == std::string::npos || close == open + 1 ||
          (close + 1 < p.size() && p[close + 1] != '['))
        throw ScenarioError("--set " + key + ": '" + p +
                            "': write an array index as name[0] or name.0");
      parts.push_back(p.substr(open + 1, close - open - 1));
      open = close + 1 < p.size() ? close + 1 : std::string::npos;
    }
  }
  toml::node* node = &root;
  for (std::size_t k = 0; k + 1 < parts.size(); ++k) node = child(*node, parts[k], true, key);
  // the value's source is the command line: errors about it name "--set KEY=VALUE", not a line
  // of the scenario file (TableReader::where)
  const std::string source = "--set " + assignment;
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + value, source);
  } catch (const toml::parse_error&) {
    std::string quoted; // a bare word: a string
    for (const char c : value) {
      if (c == '"' || c == '\\') quoted += '\\';
      quoted += c;
    }
    try {
      parsed = toml::parse("v = \"" + quoted + "\"", source);
    } catch (const toml::parse_error&) {
      throw ScenarioError(source + ": not a TOML value (a number, \"text\", [a, b] or true)");
    }
  }
  if (auto* t = node->as_table())
    t->insert_or_assign(parts.back(), std::move(*parsed.get("v")));
  else
    throw ScenarioError("--set " + key + ": the parent of '" + parts.back() + "' is not a table");
}

// ---- sections --------------------------------------------------------------------------------

Rect rect(TableReader& r, std::string_view key) {
  const auto v = r.optional_numbers(key);
  if (!v || v->size() != 4 || (*v)[2] <= (*v)[0] || (*v)[3] <= (*v)[1])
    r.fail(key, "expected [x_min, y_min, x_max, y_max] in m with x_max > x_min, y_max > y_min");
  return {{(*v)[0], (*v)[1]}, {(*v)[2], (*v)[3]}};
}

void read_simulation(TableReader& r, SimulationSection& s) {
  s.duration = r.number("duration", s.duration, 0.0, inf, "> 0 s");
  if (s.duration <= 0.0) r.fail("duration", "must be > 0 s");
  // a number, or "auto" (the collision time / timestep_factor)
  if (r.has("timestep")) {
    if (r.is_number("timestep")) {
      s.timestep = r.optional_number("timestep", 0.0, inf, "> 0 s or \"auto\"");
      if (!(*s.timestep > 0.0)) r.fail("timestep", "must be > 0 s or \"auto\"");
    } else if (r.text("timestep", "auto") != "auto") {
      r.fail("timestep", "allowed: a number in s, or \"auto\"");
    }
  }
  s.timestep_factor = r.number("timestep_factor", s.timestep_factor, 1.0, 1e6, ">= 1");
  s.integrator = parse_integrator(r.choice("integrator", "gear", {"gear", "verlet"}));
  s.verlet_velocity =
      parse_verlet_velocity(r.choice("verlet_velocity", "predicted", {"predicted", "half_step"}));
  s.lever_arm = parse_lever_arm(
      r.choice("lever_arm", "contact_point", {"contact_point", "radius", "granular"}));
  s.normal_law = parse_normal_law(r.choice("normal_law", "linear", NormalLaws::names));
  const std::string damping = r.choice("linear_damping", "never_attractive", linear_damping_names);
  for (std::size_t k = 0; k < linear_damping_names.size(); ++k)
    if (damping == linear_damping_names[k]) s.linear_damping = static_cast<LinearDamping>(k);
  if (s.linear_damping != LinearDamping::never_attractive &&
      s.normal_law != law_id<LinearSpringDashpot>)
    r.fail("linear_damping", "applies to the linear normal law only (the Hertz law's dashpot never "
                             "pulls); allowed with normal_law = \"" +
                                 std::string(name_of(s.normal_law)) + "\": never_attractive");
  s.tangential_law =
      parse_tangential_law(r.choice("tangential_law", "cundall_strack", TangentialLaws::names));
  s.gravity = r.vec2("gravity", s.gravity);
  s.seed = static_cast<std::uint64_t>(r.integer("seed", static_cast<std::int64_t>(s.seed), 0,
                                                std::numeric_limits<std::int64_t>::max()));
  s.threads = static_cast<int>(r.integer("threads", s.threads, 0, 1024));
  s.skin = r.number("skin", s.skin, 0.0, inf, ">= 0 m (0: automatic)");
  s.sort_every =
      static_cast<std::uint64_t>(r.integer("sort_every", static_cast<std::int64_t>(s.sort_every), 0,
                                           std::numeric_limits<std::int64_t>::max()));
  s.impact_speed = r.number("impact_speed", s.impact_speed, 1e-9, inf, "> 0 m/s");
}

Material read_material(TableReader& r, std::size_t index) {
  Material m;
  m.name = r.text("name", "material" + std::to_string(index));
  for (const MaterialKey& k : material_keys) {
    const double x = r.number(k.name, k.fallback, k.minus_one_derives ? -1.0 : k.lowest, k.highest,
                              k.allowed.data());
    if (!allowed_value(k, x))
      r.fail(k.name, fmt::format("{:g} is out of range; allowed: {}", x, k.allowed));
    m.*k.field = x;
  }
  m.rigid = r.boolean("rigid", false);
  return m;
}

// A name thermo.csv's columns (force_NAME_x) and a driver's target can carry.
bool is_group_name(const std::string& name) {
  return !name.empty() && name.find_first_not_of(
                              "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") ==
                              std::string::npos;
}

void read_size(TableReader& r, SizeSpec& s) {
  s.distribution = r.choice("distribution", "uniform", {"uniform", "wentworth", "discrete"});
  s.mean_radius = r.number("mean_radius", s.mean_radius, 1e-12, inf, "> 0 m");
  s.spread = r.number("spread", s.spread, 0.0, inf, ">= 0 m");
  if (s.spread >= s.mean_radius) r.fail("spread", "must be smaller than mean_radius");
  s.wentworth_class = r.text("class", "");
  s.radii = r.numbers("radii", 1e-12, inf, "> 0 m");
  s.fractions = r.numbers("fractions", 0.0, 1.0, "[0, 1]");
  if (s.distribution == "wentworth" && s.wentworth_class.empty())
    r.fail("class", "required with distribution = \"wentworth\"");
  if (s.distribution == "discrete") {
    if (s.radii.empty() || s.radii.size() != s.fractions.size())
      r.fail("fractions", "distribution = \"discrete\" needs radii and fractions of equal length");
    double sum = 0.0;
    for (const double f : s.fractions) sum += f;
    if (std::abs(sum - 1.0) > 1e-9) r.fail("fractions", "must add up to 1");
  }
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
    region.name = t.text("name", "");
    if (region.name.empty() ||
        region.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") != std::string::npos)
      t.fail("name", "expected a word of lower-case letters, digits and _ (its columns' prefix)");
    for (const StressRegion& other : o.stress_regions)
      if (other.name == region.name) t.fail("name", "'" + region.name + "' is given twice");
    if (!t.has("region")) t.fail("region", "missing; expected [x_min, y_min, x_max, y_max] in m");
    region.region = rect(t, "region");
    t.finish();
    o.stress_regions.push_back(std::move(region));
  }
}

void read_output(TableReader& r, OutputSection& o) {
  o.thermo_interval = r.number("thermo_interval", o.thermo_interval, 1e-12, inf, "> 0 s");
  o.snapshot_interval =
      r.number("snapshot_interval", o.snapshot_interval, 0.0, inf, ">= 0 s (0: none)");
  o.checkpoint_interval = r.number("checkpoint_interval", o.checkpoint_interval, 0.0, inf,
                                   ">= 0 s (0: only at the end)");
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
template <class F>
void section(TableReader& top, const char* name, const std::string& file, F&& read) {
  if (const toml::table* t = top.table(name)) {
    TableReader r(*t, file, name);
    read(r);
    r.finish();
  }
}

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
  if (name.empty()) return 0;
  std::string names;
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    if (s.materials[i].name == name) return static_cast<std::uint16_t>(i);
    names += (names.empty() ? "" : ", ") + s.materials[i].name;
  }
  throw ScenarioError("key '" + key + "': no material named '" + name + "'; defined: " + names);
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
  s.name = top.text("name", s.name);
  // the name makes the default run folder runs/NAME: one plain folder name, nothing that climbs
  if (s.name.empty() || s.name == "." || s.name == ".." ||
      s.name.find_first_not_of(
          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.-") != std::string::npos)
    top.fail("name", "'" + s.name +
                         "'; allowed: letters, digits, '_', '-' and '.' (it names the "
                         "run folder runs/NAME)");
  s.description = top.text("description", "");
  if (const toml::table* t = top.table("simulation")) {
    TableReader r(*t, file, "simulation");
    read_simulation(r, s.simulation);
    r.finish();
  }
  std::size_t k = 0;
  for (const toml::table* t : top.tables("materials")) {
    TableReader r(*t, file, "materials." + std::to_string(k));
    s.materials.push_back(read_material(r, k++));
    r.finish();
  }
  if (s.materials.empty()) {
    Material m; // every key at its default
    m.name = "grain";
    s.materials.push_back(m);
  }
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
  for (std::size_t m = 0; m < s.materials.size(); ++m)
    for (std::size_t n = m + 1; n < s.materials.size(); ++n)
      if (s.materials[m].name == s.materials[n].name)
        throw ScenarioError(file + ": two materials are named '" + s.materials[m].name + "'");
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
  toml::table root;
  try {
    root = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw ScenarioError(file + ":" + std::to_string(e.source().begin.line) + ": " +
                        std::string(e.description()));
  }
  for (const auto& o : overrides) apply_override(root, o);
  return load_root(root, file, true);
}

Scenario load_scenario_file(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path + ": cannot be read (does it exist?)");
  std::stringstream buf;
  buf << in.rdbuf();
  return load_scenario(buf.str(), path, overrides);
}

} // namespace talus
