#include "scenario/file/shared_sections.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "talus/material_keys.hpp"

namespace talus {

namespace {
using keys::inf;
} // namespace

namespace {

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

} // namespace

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

toml::table parse_with_overrides(std::string_view text, const std::string& file,
                                 const std::vector<std::string>& overrides) {
  toml::table root;
  try {
    root = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw ScenarioError(file + ":" + std::to_string(e.source().begin.line) + ": " +
                        std::string(e.description()));
  }
  for (const auto& o : overrides) apply_override(root, o);
  return root;
}

int scenario_dimension(const toml::table& root, const std::string& file) {
  const toml::table* sim = root["simulation"].as_table();
  if (!sim || !sim->contains("dimension")) return 2;
  const std::optional<std::int64_t> d = (*sim)["dimension"].value<std::int64_t>();
  if (!d || (*d != 2 && *d != 3)) {
    const toml::source_region& where = (*sim)["dimension"].node()->source();
    throw ScenarioError(fmt::format("{}:{}: key 'simulation.dimension': allowed: 2 (disks) or 3 "
                                    "(spheres)",
                                    file, where.begin.line));
  }
  return static_cast<int>(*d);
}

std::uint16_t material_index(const std::vector<Material>& materials, const std::string& name,
                             const std::string& key) {
  if (name.empty()) return 0;
  std::string names;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    if (materials[i].name == name) return static_cast<std::uint16_t>(i);
    names += (names.empty() ? "" : ", ") + materials[i].name;
  }
  throw ScenarioError("key '" + key + "': no material named '" + name + "'; defined: " + names);
}

std::string read_name(TableReader& top, std::string fallback) {
  std::string name = top.text("name", std::move(fallback));
  // the name makes the default run folder runs/NAME: one plain folder name, nothing that climbs
  if (name.empty() || name == "." || name == ".." ||
      name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.-") !=
          std::string::npos)
    top.fail("name", "'" + name +
                         "'; allowed: letters, digits, '_', '-' and '.' (it names the "
                         "run folder runs/NAME)");
  return name;
}

std::string read_region_name(TableReader& r, const std::vector<std::string>& taken) {
  const std::string name = r.text("name", "");
  if (name.empty() ||
      name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") != std::string::npos)
    r.fail("name", "expected a word of lower-case letters, digits and _ (its columns' prefix)");
  for (const std::string& other : taken)
    if (other == name) r.fail("name", "'" + name + "' is given twice");
  return name;
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

std::vector<Material> read_materials(TableReader& top, const std::string& file) {
  std::vector<Material> out;
  std::size_t k = 0;
  for (const toml::table* t : top.tables("materials")) {
    TableReader r(*t, file, "materials." + std::to_string(k));
    out.push_back(read_material(r, k++));
    r.finish();
  }
  if (out.empty()) {
    Material m; // every key at its default
    m.name = "grain";
    out.push_back(m);
  }
  for (std::size_t m = 0; m < out.size(); ++m)
    for (std::size_t n = m + 1; n < out.size(); ++n)
      if (out[m].name == out[n].name)
        throw ScenarioError(file + ": two materials are named '" + out[m].name + "'");
  return out;
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

namespace {
toml::array numbers(const std::vector<double>& v) {
  toml::array out;
  for (const double x : v) out.push_back(x);
  return out;
}
} // namespace

toml::table size_table(const SizeSpec& s) {
  return toml::table{{"distribution", s.distribution},
                     {"mean_radius", s.mean_radius},
                     {"spread", s.spread},
                     {"class", s.wentworth_class},
                     {"radii", numbers(s.radii)},
                     {"fractions", numbers(s.fractions)}};
}

toml::array materials_array(const std::vector<Material>& materials) {
  toml::array out;
  for (const Material& m : materials) {
    toml::table row{{"name", m.name}};
    for (const MaterialKey& k : material_keys) row.insert(k.name, m.*k.field);
    row.insert("rigid", m.rigid);
    out.push_back(std::move(row));
  }
  return out;
}

} // namespace talus
