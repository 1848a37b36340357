#include "cli/analyze/report_tables.hpp"

#include <sstream>

#include <fmt/core.h>

#include "talus/law_table.hpp"
#include "talus/material_keys.hpp"

namespace talus::cli {

namespace {

std::string size_text(const Scenario& s) {
  const SizeSpec& z = s.particles.size;
  if (z.distribution == "uniform")
    return z.spread > 0.0
               ? fmt::format("radius {:.4g} m +- {:.4g} m (uniform)", z.mean_radius, z.spread)
               : fmt::format("radius {:.4g} m", z.mean_radius);
  if (z.distribution == "wentworth") return "Wentworth class " + z.wentworth_class;
  std::string out = "radii";
  for (std::size_t k = 0; k < z.radii.size(); ++k)
    out += fmt::format("{} {:.4g} m ({:.3g})", k ? "," : "", z.radii[k], z.fractions[k]);
  return out + " (number fractions)";
}

std::string container_text(const GeometrySection& g) {
  std::string out = g.builder.empty() ? std::string("none") : g.builder;
  if (g.radius > 0.0) out += fmt::format(", radius {:.4g} m", g.radius);
  if (g.width > 0.0) out += fmt::format(", {:.4g} m wide", g.width);
  if (g.height > 0.0) out += fmt::format(", {:.4g} m high", g.height);
  if (g.orifice > 0.0) out += fmt::format(", orifice {:.4g} m", g.orifice);
  if (g.angular_velocity != 0.0)
    out += fmt::format(", turning at {:.4g} rad/s", g.angular_velocity);
  if (g.periodic != "none") out += ", periodic in " + g.periodic;
  return out + fmt::format("; walls of {}", g.walls);
}

// The unit in a key's allowed range, written "OP NUMBER UNIT ..." (" N/m"; "" without one).
std::string unit_of(const MaterialKey& key) {
  std::istringstream words{std::string(key.allowed)};
  std::string op, number, unit;
  words >> op >> number >> unit;
  const bool comparison = op == ">" || op == ">=" || op == "<" || op == "<=";
  return comparison && !unit.empty() && unit.front() != '(' ? " " + unit : "";
}

} // namespace

Rows scenario_rows(const Scenario& s) {
  Rows rows{
      {"normal law", std::string(name_of(s.simulation.normal_law))},
      {"tangential law", std::string(name_of(s.simulation.tangential_law))},
      {"integrator", std::string(to_string(s.simulation.integrator))},
      {"timestep", s.simulation.timestep ? fmt::format("{:.4g} s", *s.simulation.timestep)
                                         : fmt::format("auto: the shortest collision time / {:g}",
                                                       s.simulation.timestep_factor)},
      {"duration", fmt::format("{:.4g} s", s.simulation.duration)},
      {"gravity",
       fmt::format("({:.4g}, {:.4g}) m/s^2", s.simulation.gravity.x, s.simulation.gravity.y)},
      {"container", container_text(s.geometry)},
      {"grains", fmt::format("{} counted{}, {}s, {}", s.particles.count,
                             s.particles.list.empty()
                                 ? std::string()
                                 : fmt::format(" and {} listed", s.particles.list.size()),
                             s.particles.shape == Shape::disk ? "disk" : "sphere", size_text(s))},
      {"packing", std::string(s.packing.method)},
  };
  for (std::size_t k = 0; k < s.materials.size(); ++k) {
    const Material& m = s.materials[k];
    std::string keys;
    for (const MaterialKey& key : material_keys) {
      const double v = m.*key.field;
      const std::string value = key.minus_one_derives && v == -1.0
                                    ? std::string("derived")
                                    : fmt::format("{:.4g}{}", v, unit_of(key));
      keys += fmt::format("{}{} = {}", keys.empty() ? "" : ", ", key.name, value);
    }
    rows.emplace_back(fmt::format("material {} '{}'", k, m.name), keys);
  }
  if (!s.stages.empty()) rows.emplace_back("stages", fmt::format("{}", s.stages.size()));
  return rows;
}

Rows run_rows(const nlohmann::json& run) {
  // run.json's keys in words, with their units (docs/file-formats.md)
  static const std::pair<const char*, const char*> named[] = {
      {"particles", "particles"},
      {"steps", "steps"},
      {"time", "simulated time [s]"},
      {"timestep", "timestep [s]"},
      {"collision_time", "shortest collision time [s]"},
      {"integrator", "integrator"},
      {"threads", "threads used"},
      {"step", "the step specialised to the scene"},
      {"settle_time", "settling before the run [s]"},
      {"wall_seconds", "wall time, every session [s]"},
      {"particle_steps_per_second", "particle-steps per second (last session)"},
      {"memory_estimate_bytes", "memory expected [bytes]"},
      {"peak_memory_bytes", "peak memory, last session [bytes]"},
      {"ended_by", "ended by"},
      {"talus_version", "talus version"},
      {"seed", "seed"},
  };
  Rows rows;
  for (const auto& [key, words] : named) {
    if (!run.contains(key)) continue;
    const nlohmann::json& v = run.at(key);
    rows.emplace_back(words, v.is_string()         ? v.get<std::string>()
                             : v.is_number_float() ? fmt::format("{:.6g}", v.get<double>())
                                                   : v.dump());
  }
  return rows;
}

} // namespace talus::cli
