#include "scenario/file/toml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace talus {

namespace {
std::set<std::string>& registry() {
  static std::set<std::string> keys;
  return keys;
}

// "materials.0" -> "materials": the documented name of a table inside an array of tables.
std::string generic(const std::string& path) {
  std::string out;
  std::stringstream in(path);
  std::string part;
  while (std::getline(in, part, '.')) {
    if (!part.empty() && std::all_of(part.begin(), part.end(), ::isdigit)) continue;
    out += (out.empty() ? "" : ".") + part;
  }
  return out;
}

std::string show(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}
} // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

TableReader::TableReader(const toml::table& table, std::string file, std::string path)
    : table_(table), file_(std::move(file)), path_(std::move(path)) {}

const std::set<std::string>& TableReader::known_keys() {
  return registry();
}

std::string TableReader::qualified(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

std::string TableReader::where(const toml::node* node) const {
  // a value given on the command line (load.cpp, apply_override) names its --set
  if (node && node->source().path && node->source().path->starts_with("--set "))
    return *node->source().path;
  // a key missing from a table the command line gave: that --set
  if (!node && table_.source().path && table_.source().path->starts_with("--set "))
    return *table_.source().path;
  const auto line = node ? node->source().begin.line : table_.source().begin.line;
  std::string out = file_;
  if (line > 0) out.append(":").append(std::to_string(line));
  return out;
}

void TableReader::fail(std::string_view key, const std::string& problem) const {
  const toml::node* node = table_.get(key);
  throw ScenarioError(where(node) + ": key '" + qualified(key) + "': " + problem);
}

void TableReader::fail_table(const std::string& problem) const {
  throw ScenarioError(where(nullptr) + ": [" + (path_.empty() ? "top level" : path_) +
                      "]: " + problem);
}

bool TableReader::has(std::string_view key) {
  return get(key) != nullptr; // a key asked about is a key of the table, for finish()'s hint
}

const toml::node* TableReader::get(std::string_view key) {
  read_.emplace(key);
  registry().insert(generic(qualified(key)));
  return table_.get(key);
}

double TableReader::number(std::string_view key, double fallback, double min, double max,
                           const char* allowed) {
  return optional_number(key, min, max, allowed).value_or(fallback);
}

std::optional<double> TableReader::optional_number(std::string_view key, double min, double max,
                                                   const char* allowed) {
  const toml::node* n = get(key);
  if (!n) return std::nullopt;
  const auto v = n->value<double>(); // integers convert too
  if (!v) fail(key, "expected a number; allowed: " + std::string(allowed));
  if (!std::isfinite(*v) || *v < min || *v > max)
    fail(key, show(*v) + " is out of range; allowed: " + allowed);
  return *v;
}

std::int64_t TableReader::integer(std::string_view key, std::int64_t fallback, std::int64_t min,
                                  std::int64_t max) {
  const toml::node* n = get(key);
  if (!n) return fallback;
  const auto v = n->value_exact<std::int64_t>();
  const std::string range =
      "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (!v) fail(key, "expected " + range);
  if (*v < min || *v > max) fail(key, std::to_string(*v) + " is out of range; allowed: " + range);
  return *v;
}

bool TableReader::boolean(std::string_view key, bool fallback) {
  const toml::node* n = get(key);
  if (!n) return fallback;
  const auto v = n->value_exact<bool>();
  if (!v) fail(key, "expected true or false");
  return *v;
}

std::string TableReader::text(std::string_view key, std::string fallback) {
  const toml::node* n = get(key);
  if (!n) return fallback;
  const auto v = n->value_exact<std::string>();
  if (!v) fail(key, "expected a string in quotes");
  return *v;
}

std::string TableReader::choice(std::string_view key, std::string fallback,
                                std::span<const std::string_view> allowed) {
  std::string v = text(key, std::move(fallback));
  std::string list;
  for (const auto a : allowed) {
    if (a == v) return v;
    list += (list.empty() ? "" : ", ") + std::string(a);
  }
  fail(key, "'" + v + "' is not one of the allowed values: " + list);
}

std::vector<std::string> TableReader::texts(std::string_view key) {
  const toml::node* n = get(key);
  std::vector<std::string> out;
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) fail(key, "expected an array of strings, e.g. [\"speed\", \"force+chains\"]");
  for (const toml::node& e : *a) {
    const auto v = e.value_exact<std::string>();
    if (!v) fail(key, "expected an array of strings in quotes");
    out.push_back(*v);
  }
  return out;
}

Vec2 TableReader::vec2(std::string_view key, Vec2 fallback) {
  const toml::node* n = get(key);
  if (!n) return fallback;
  const toml::array* a = n->as_array();
  if (!a || a->size() != 2 || !(*a)[0].value<double>() || !(*a)[1].value<double>())
    fail(key, "expected two numbers [x, y]");
  const Vec2 v{*(*a)[0].value<double>(), *(*a)[1].value<double>()};
  if (!std::isfinite(v.x) || !std::isfinite(v.y))
    fail(key, "[" + show(v.x) + ", " + show(v.y) + "]; allowed: two finite numbers [x, y]");
  return v;
}

std::optional<std::vector<double>> TableReader::optional_numbers(std::string_view key) {
  const toml::node* n = get(key);
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  if (!a) fail(key, "expected an array of numbers [a, b, ...]");
  std::vector<double> out;
  for (const auto& e : *a) {
    const auto v = e.value<double>();
    if (!v) fail(key, "expected an array of numbers [a, b, ...]");
    if (!std::isfinite(*v)) fail(key, show(*v) + " in the array; allowed: finite numbers");
    out.push_back(*v);
  }
  return out;
}

std::vector<double> TableReader::numbers(std::string_view key, double min, double max,
                                         const char* allowed) {
  auto v = optional_numbers(key).value_or(std::vector<double>{});
  for (const double x : v)
    if (!std::isfinite(x) || x < min || x > max)
      fail(key, "value " + show(x) + " is out of range; allowed: " + allowed);
  return v;
}

const toml::table* TableReader::table(std::string_view key) {
  const toml::node* n = get(key);
  if (!n) return nullptr;
  if (!n->is_table()) fail(key, "expected a table");
  return n->as_table();
}

std::vector<const toml::table*> TableReader::tables(std::string_view key) {
  const toml::node* n = get(key);
  std::vector<const toml::table*> out;
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a || (!a->empty() && !a->is_array_of_tables())) // [] has none: "no walls", for --set
    fail(key, "expected an array of tables, written [[" + qualified(key) + "]]");
  for (const auto& e : *a) out.push_back(e.as_table());
  return out;
}

void TableReader::finish() const {
  for (const auto& [k, v] : table_) {
    const std::string_view key = k.str();
    if (read_.count(key)) continue;
    std::string best;
    std::size_t best_d = std::numeric_limits<std::size_t>::max();
    for (const auto& known : read_)
      if (const std::size_t d = edit_distance(key, known); d < best_d) best_d = d, best = known;
    std::string msg = "unknown key";
    if (!best.empty() && best_d <= std::max<std::size_t>(2, key.size() / 3))
      msg += "; did you mean '" + best + "'?";
    std::string list;
    for (const auto& known : read_) list += (list.empty() ? "" : ", ") + known;
    msg += " (keys of [" + (path_.empty() ? std::string("top level") : path_) + "]: " + list + ")";
    throw ScenarioError(where(&v) + ": key '" + qualified(key) + "': " + msg);
  }
}

} // namespace talus
