#include "scenario/file/stages.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "scenario/file/load.hpp"
#include "talus/material_keys.hpp"

namespace talus {

namespace {

using keys::inf;

// The changes of a stage's `set` table as "key=value": its tables give dotted keys
// ([stages.set.simulation] gravity = ...: simulation.gravity), and a quoted dotted key names its
// key whole ("simulation.gravity" = ...).
void flatten(const toml::table& t, const std::string& prefix, std::vector<std::string>& out) {
  for (const auto& [k, v] : t) {
    const std::string key =
        prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const toml::table* sub = v.as_table()) {
      flatten(*sub, key, out);
      continue;
    }
    std::ostringstream value;
    v.visit([&](const auto& node) { value << node; });
    out.push_back(key + "=" + with_shortest_floats(value.str()));
  }
}

constexpr std::array<std::string_view, 12> changeable_settings{"simulation.gravity",
                                                               "simulation.tangential_law",
                                                               "simulation.timestep",
                                                               "simulation.timestep_factor",
                                                               "geometry.gate",
                                                               "geometry.segments",
                                                               "geometry.angular_velocity",
                                                               "geometry.lid_speed",
                                                               "output.thermo_interval",
                                                               "output.snapshot_interval",
                                                               "output.track_interval",
                                                               "output.checkpoint_interval"};
// a driver's motion (not its type or target)
constexpr std::array<std::string_view, 16> changeable_driver_keys{
    "velocity",    "angular_velocity", "amplitude",       "frequency",
    "phase",       "direction",        "centre",          "force",
    "stress",      "max_speed",        "relaxation",      "slide_speed",
    "strain_rate", "pressure",         "max_strain_rate", "shear_rate"};

// Whether key is PREFIX.N.NAME with N a number, and NAME then.
bool indexed(const std::string& key, std::string_view prefix, std::string& name) {
  if (!key.starts_with(prefix)) return false;
  const std::size_t at = prefix.size(), dot = key.find('.', at);
  if (dot == std::string::npos || dot == at || key.find_first_not_of("0123456789", at) != dot)
    return false;
  name = key.substr(dot + 1);
  return true;
}

// The conditions a stage may end on, and the keys each needs.
struct Condition {
  std::string_view until;
  std::array<std::string_view, 2> needs;
};
constexpr std::array<Condition, 8> conditions{{{"none", {}},
                                               {"settled", {}},
                                               {"kinetic_below", {"kinetic"}},
                                               {"kinetic_above", {"kinetic"}},
                                               {"wall_force_above", {"group", "force"}},
                                               {"wall_position_below", {"group", "position"}},
                                               {"wall_position_above", {"group", "position"}},
                                               {"grains_below", {"height", "count"}}}};

// A stage's condition and the keys it needs: each of them given, and no other.
void read_condition(TableReader& r, StageSection& st) {
  std::array<std::string_view, conditions.size()> names;
  for (std::size_t k = 0; k < conditions.size(); ++k) names[k] = conditions[k].until;
  st.until = r.choice("until", "none", std::span<const std::string_view>(names));
  const Condition& c = *std::find_if(conditions.begin(), conditions.end(),
                                     [&](const Condition& x) { return x.until == st.until; });
  for (const std::string_view key : {"kinetic", "group", "force", "position", "height", "count"}) {
    const bool needed = std::find(c.needs.begin(), c.needs.end(), key) != c.needs.end();
    if (needed && !r.has(key))
      r.fail(key, fmt::format("missing; until = \"{}\" needs it", st.until));
    if (!needed && r.has(key))
      r.fail(key, fmt::format("does not apply to until = \"{}\"", st.until));
  }
  st.kinetic = r.number("kinetic", 0.0, 1e-300, inf, "> 0 J");
  st.group = r.text("group", "");
  st.force = r.number("force", 0.0, 0.0, inf, ">= 0 N");
  st.position = r.number("position", 0.0, -inf, inf, "a height, m");
  st.height = r.number("height", 0.0, -inf, inf, "a height, m");
  st.count =
      static_cast<std::size_t>(r.integer("count", 1, 1, std::numeric_limits<std::int64_t>::max()));
}

} // namespace

std::string change_key(const std::string& change) {
  std::string key = change.substr(0, change.find('='));
  std::string out;
  for (const char c : key) {
    if (c == '[')
      out += '.';
    else if (c != ']')
      out += c;
  }
  return out;
}

bool changeable_during_run(const std::string& key) {
  if (std::find(changeable_settings.begin(), changeable_settings.end(), key) !=
      changeable_settings.end())
    return true;
  std::string name;
  if (indexed(key, "drivers.", name))
    return std::find(changeable_driver_keys.begin(), changeable_driver_keys.end(), name) !=
           changeable_driver_keys.end();
  // materials.N.KEY, for a contact key of the table
  if (!indexed(key, "materials.", name)) return false;
  return name != "density" && std::any_of(material_keys.begin(), material_keys.end(),
                                          [&](const MaterialKey& k) { return k.name == name; });
}

std::string changeable_keys_text() {
  std::string out;
  for (const std::string_view k : changeable_settings) out.append(k).append(", ");
  out += "drivers.N.KEY for a driver's ";
  for (const std::string_view k : changeable_driver_keys) out.append(k).append(", ");
  return out + "and materials.N.KEY for a material's keys but density";
}

std::vector<StageSection> read_stages(TableReader& top, const std::string& file) {
  std::vector<StageSection> stages;
  const std::vector<const toml::table*> tables = top.tables("stages");
  for (std::size_t k = 0; k < tables.size(); ++k) {
    TableReader r(*tables[k], file, "stages." + std::to_string(k));
    StageSection st;
    st.name = r.text("name", "stage" + std::to_string(k));
    const bool last = k + 1 == tables.size();
    if (!last && !r.has("duration"))
      r.fail("duration", "missing; every stage but the last needs one (s, > 0)");
    st.duration = r.number("duration", 0.0, 1e-12, inf, "> 0 s");
    read_condition(r, st);
    st.then = r.choice("then", "next", {"next", "end"});
    if (st.until == "none" && r.has("then"))
      r.fail("then", "applies only with a condition (until)");
    if (const toml::table* set = r.table("set")) flatten(*set, "", st.set);
    if (k == 0 && !st.set.empty())
      r.fail("set", "the first stage's settings are the scenario's own: give them in its "
                    "sections, and changes in the stages after it");
    for (const std::string& c : st.set)
      if (!changeable_during_run(change_key(c)))
        r.fail("set", fmt::format("'{}' cannot change during a run; allowed: {}", change_key(c),
                                  changeable_keys_text()));
    r.finish();
    stages.push_back(std::move(st));
  }
  return stages;
}

} // namespace talus
