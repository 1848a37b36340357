#include "scenario/file/differences.hpp"

#include <sstream>
#include <unordered_map>

#include <toml++/toml.h>

#include "scenario/file/load.hpp"

namespace talus {

namespace {

std::string text_of(const toml::node& n) {
  std::ostringstream o;
  n.visit([&](const auto& v) { o << v; });
  return o.str();
}

bool is_array_of_tables(const toml::node& n) {
  const toml::array* a = n.as_array();
  return a && !a->empty() && a->is_array_of_tables();
}

// Every leaf of `n` under `key`: a table's keys and an array of tables' entries by index; other
// arrays (a vector, a list of words) are one value.
void leaves(const toml::node& n, const std::string& key,
            std::vector<std::pair<std::string, const toml::node*>>& out) {
  const std::string prefix = key.empty() ? "" : key + ".";
  if (const toml::table* t = n.as_table()) {
    for (const auto& [k, v] : *t) leaves(v, prefix + std::string(k.str()), out);
  } else if (is_array_of_tables(n)) {
    const toml::array& a = *n.as_array();
    for (std::size_t i = 0; i < a.size(); ++i) leaves(a[i], prefix + std::to_string(i), out);
  } else {
    out.emplace_back(key, &n);
  }
}

} // namespace

std::vector<KeyDifference> scenario_differences(const Scenario& a, const Scenario& b) {
  const toml::table ta = toml::parse(to_toml(a)), tb = toml::parse(to_toml(b));
  std::vector<std::pair<std::string, const toml::node*>> la, lb;
  leaves(ta, "", la);
  leaves(tb, "", lb);
  std::unordered_map<std::string, const toml::node*> in_b(lb.begin(), lb.end());
  std::vector<KeyDifference> out;
  for (const auto& [key, node] : la) {
    const auto other = in_b.find(key);
    if (other == in_b.end())
      out.push_back({key, std::nullopt});
    else if (text_of(*node) != text_of(*other->second))
      out.push_back({key, text_of(*other->second)});
  }
  const std::unordered_map<std::string, const toml::node*> in_a(la.begin(), la.end());
  for (const auto& [key, node] : lb)
    if (!in_a.count(key)) out.push_back({key, text_of(*node)});
  return out;
}

} // namespace talus
