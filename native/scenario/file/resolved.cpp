// Scenario -> TOML, with every key written: the run folder's scenario.toml reruns the same run.
#include <cctype>
#include <charconv>
#include <sstream>
#include <string_view>

#include <fmt/format.h>

#include "scenario/file/load.hpp"
#include "scenario/file/shared_sections.hpp"
#include "scenario/file/simulation_keys.hpp"

namespace talus {

namespace {

toml::array vec(Vec2 v) {
  return toml::array{v.x, v.y};
}
toml::array rect(const Rect& r) {
  return toml::array{r.lo.x, r.lo.y, r.hi.x, r.hi.y};
}

// toml++ writes a float with 17 significant digits (0.10000000000000001 for 0.1): each float
// outside a string is written again as the shortest text that reads back to the same double.
std::string shortest_floats(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  char quote = 0;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (quote) { // inside a string: copied as it is, escapes included
      out += c;
      if (c == '\\' && quote == '"' && i + 1 < text.size())
        out += text[++i];
      else if (c == quote)
        quote = 0;
      ++i;
      continue;
    }
    if (c == '"' || c == '\'') quote = c;
    if (c == '#') { // a comment runs to the end of the line
      const std::size_t end = text.find('\n', i);
      out.append(text, i, end == std::string::npos ? std::string::npos : end - i);
      i = end == std::string::npos ? text.size() : end;
      continue;
    }
    const bool starts_number =
        (c == '-' || c == '+' || std::isdigit(static_cast<unsigned char>(c))) &&
        (i == 0 || std::string_view(" [=,").find(text[i - 1]) != std::string_view::npos);
    if (starts_number) {
      std::size_t end = i + 1;
      while (end < text.size() &&
             std::string_view("0123456789.eE+-_").find(text[end]) != std::string_view::npos)
        ++end;
      const std::string token = text.substr(i, end - i);
      double v = 0.0;
      const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
      if (ec == std::errc() && ptr == token.data() + token.size() &&
          token.find_first_of(".eE") != std::string::npos) {
        std::string shortest = fmt::format("{}", v);
        if (shortest.find_first_of(".eEn") == std::string::npos) shortest += ".0"; // still a float
        out += shortest;
      } else {
        out += token;
      }
      i = end;
      continue;
    }
    out += c;
    ++i;
  }
  return out;
}

toml::table simulation_table(const SimulationSection& sim) {
  toml::table t;
  write_clock_and_laws(t, sim);
  t.insert("integrator", std::string(to_string(sim.integrator)));
  t.insert("gravity", vec(sim.gravity));
  t.insert("threads", sim.threads);
  return t;
}

toml::table particles_table(const ParticlesSection& p) {
  const toml::table size = size_table(p.size);
  toml::array explicit_list;
  for (const ExplicitParticle& e : p.list) {
    toml::table t{{"position", vec(e.position)},
                  {"radius", e.radius},
                  {"velocity", vec(e.velocity)},
                  {"angular_velocity", e.angular_velocity},
                  {"mass", e.mass},
                  {"kind", e.kind},
                  {"material", e.material}};
    if (e.kind == "fixed") t.insert("group", e.group); // a free grain has none
    explicit_list.push_back(std::move(t));
  }
  toml::table particles{{"count", static_cast<std::int64_t>(p.count)},
                        {"shape", p.shape == Shape::disk ? "disk" : "sphere"},
                        {"material", p.material},
                        {"size", size}};
  if (!explicit_list.empty()) particles.insert("list", explicit_list);
  return particles;
}

toml::table packing_table(const PackingSection& p) {
  toml::table packing{{"method", p.method},
                      {"settle_energy", p.settle_energy},
                      {"settle_max_time", p.settle_max_time}};
  if (p.region) packing.insert("region", rect(*p.region));
  return packing;
}

toml::table geometry_table(const GeometrySection& g) {
  toml::table geometry{{"builder", g.builder},
                       {"width", g.width},
                       {"height", g.height},
                       {"orifice", g.orifice},
                       {"wall_angle", g.wall_angle},
                       {"lid_speed", g.lid_speed},
                       {"radius", g.radius},
                       {"angular_velocity", g.angular_velocity},
                       {"walls", g.walls},
                       {"wall_particle_radius", g.wall_particle_radius},
                       {"wall_material", g.wall_material},
                       {"periodic", g.periodic}};
  if (g.orifice_x) geometry.insert("orifice_x", *g.orifice_x);
  if (g.bin_depth) geometry.insert("bin_depth", *g.bin_depth);
  if (g.gate) geometry.insert("gate", true);
  if (g.box) geometry.insert("box", rect(*g.box));
  toml::array segments;
  for (const SegmentSpec& seg : g.segments)
    segments.push_back(toml::table{{"a", vec(seg.a)}, {"b", vec(seg.b)}, {"group", seg.group}});
  if (!segments.empty()) geometry.insert("segments", segments);
  return geometry;
}

toml::array drivers_array(const std::vector<DriverSection>& drivers) {
  toml::array out;
  for (const DriverSection& d : drivers) {
    if (d.type == "cell") { // no target, and the mode the file gave
      toml::table t{{"type", d.type}};
      if (d.pressure > 0.0) {
        t.insert("pressure", d.pressure);
        t.insert("max_strain_rate", d.max_strain_rate);
        t.insert("relaxation", d.relaxation);
      } else {
        t.insert("strain_rate", vec(d.strain_rate));
      }
      if (d.shear_rate != 0.0) t.insert("shear_rate", d.shear_rate);
      out.push_back(std::move(t));
      continue;
    }
    toml::table t{{"type", d.type},
                  {"target", d.target},
                  {"amplitude", d.amplitude},
                  {"frequency", d.frequency},
                  {"phase", d.phase},
                  {"direction", vec(d.direction)},
                  {"velocity", vec(d.velocity)},
                  {"centre", vec(d.centre)},
                  {"angular_velocity", d.angular_velocity}};
    if (d.type == "servo") { // the target the file gave, force or stress
      t.insert(d.stress > 0.0 ? "stress" : "force", d.stress > 0.0 ? d.stress : d.force);
      t.insert("max_speed", d.max_speed);
      t.insert("relaxation", d.relaxation);
      t.insert("slide_speed", d.slide_speed);
    }
    out.push_back(std::move(t));
  }
  return out;
}

toml::table track_table(const TrackSection& t) {
  toml::array ids;
  for (const auto id : t.ids) ids.push_back(static_cast<std::int64_t>(id));
  return toml::table{{"ids", ids},
                     {"select", t.select},
                     {"at", vec(t.at)},
                     {"count", static_cast<std::int64_t>(t.count)}};
}

toml::table output_table(const OutputSection& o) {
  toml::array pictures;
  for (const auto& name : o.pictures) pictures.push_back(name);
  toml::table t{{"thermo_interval", o.thermo_interval},
                {"snapshot_interval", o.snapshot_interval},
                {"checkpoint_interval", o.checkpoint_interval},
                {"track_interval", o.track_interval},
                {"thesis_out", o.thesis_out},
                {"contacts", o.contacts},
                {"energy_ledger", o.energy_ledger},
                {"stress", o.stress},
                {"picture", o.picture},
                {"pictures", pictures},
                {"movie", o.movie},
                {"movie_color", o.movie_color}};
  if (o.stress_region) t.insert("stress_region", rect(*o.stress_region));
  if (!o.stress_regions.empty()) {
    toml::array regions;
    for (const StressRegion& r : o.stress_regions)
      regions.push_back(toml::table{{"name", r.name}, {"region", rect(r.region)}});
    t.insert("stress_regions", regions);
  }
  return t;
}

toml::table frost_table(const FrostSection& f) {
  return toml::table{{"model", f.model},
                     {"heave_factor", f.heave_factor},
                     {"kinetic_threshold", f.kinetic_threshold},
                     {"min_interval", f.min_interval},
                     {"cycles", static_cast<std::int64_t>(f.cycles)},
                     {"permafrost_depth", f.permafrost_depth},
                     {"heave_strain", f.heave_strain},
                     {"conductivity_ratio", f.conductivity_ratio},
                     {"stone_water", f.stone_water},
                     {"ice_content", f.ice_content},
                     {"crust_length", f.crust_length},
                     {"column_width", f.column_width},
                     {"stone_radius", f.stone_radius},
                     {"freeze_time", f.freeze_time},
                     {"thaw_time", f.thaw_time},
                     {"frost_pull", f.frost_pull},
                     {"thawed_material", f.thawed_material}};
}

// Each stage with its changes as quoted dotted keys ("simulation.gravity" = [0, -9.81]).
toml::array stages_array(const std::vector<StageSection>& stages) {
  toml::array out;
  for (const StageSection& st : stages) {
    toml::table set;
    for (const std::string& c : st.set) {
      const std::size_t eq = c.find('=');
      toml::table parsed = toml::parse("v = " + c.substr(eq + 1));
      set.insert(c.substr(0, eq), std::move(*parsed.get("v")));
    }
    toml::table t{{"name", st.name}};
    // the last stage may have none (it lasts to the run's end): 0 would read back as refused
    if (st.duration > 0.0) t.insert("duration", st.duration);
    t.insert("until", st.until);
    if (st.until.starts_with("kinetic")) t.insert("kinetic", st.kinetic);
    if (st.until.starts_with("wall")) t.insert("group", st.group);
    if (st.until == "wall_force_above") t.insert("force", st.force);
    if (st.until.starts_with("wall_position")) t.insert("position", st.position);
    if (st.until == "grains_below") {
      t.insert("height", st.height);
      t.insert("count", static_cast<std::int64_t>(st.count));
    }
    if (st.until != "none") t.insert("then", st.then);
    if (!set.empty()) t.insert("set", std::move(set));
    out.push_back(std::move(t));
  }
  return out;
}

} // namespace

std::string with_shortest_floats(const std::string& toml_text) {
  return shortest_floats(toml_text);
}

std::string to_toml(const Scenario& s) {
  toml::table root;
  root.insert("name", s.name);
  root.insert("description", s.description);
  root.insert("simulation", simulation_table(s.simulation));
  root.insert("materials", materials_array(s.materials));
  root.insert("particles", particles_table(s.particles));
  root.insert("packing", packing_table(s.packing));
  root.insert("geometry", geometry_table(s.geometry));
  const toml::array drivers = drivers_array(s.drivers);
  if (!drivers.empty()) root.insert("drivers", drivers);
  root.insert("track", track_table(s.track));
  root.insert("output", output_table(s.output));
  root.insert("frost", frost_table(s.frost));
  if (!s.stages.empty()) root.insert("stages", stages_array(s.stages));
  std::ostringstream out;
  out << "# resolved by talus: every key with its value; `talus run` on this file reruns the run\n"
      << root << "\n";
  return shortest_floats(out.str());
}

} // namespace talus
