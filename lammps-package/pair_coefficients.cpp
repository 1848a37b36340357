#include "pair_coefficients.hpp"

#include <cmath>
#include <cstdlib>
#include <set>

#include "talus/error.hpp"
#include "talus/material_keys.hpp"

namespace talus::lammps {

namespace {

const MaterialKey* find_key(const std::string& name) {
  for (const MaterialKey& k : material_keys)
    if (k.name == name && k.name != "density") return &k;
  return nullptr;
}

double parse_number(const std::string& key, const std::string& text) {
  const std::optional<double> x = finite_number(text);
  if (!x) throw InvalidArgument("pair_coeff " + key + " = '" + text + "' is not a finite number");
  return *x;
}

} // namespace

std::optional<double> finite_number(const std::string& text) {
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(x)) return std::nullopt;
  return x;
}

std::string pair_coefficient_names() {
  std::string names;
  for (const MaterialKey& k : material_keys) {
    if (k.name == "density") continue;
    if (!names.empty()) names.append(", ");
    names.append(k.name);
  }
  return names;
}

Material parse_pair_coefficients(const std::vector<std::string>& words) {
  Material m; // every key at its default
  std::set<std::string> given;
  for (std::size_t w = 0; w < words.size(); w += 2) {
    const std::string& key = words[w];
    if (!given.insert(key).second)
      throw InvalidArgument("pair_coeff: key '" + key +
                            "' is given twice; allowed: each key once per pair_coeff");
    if (key == "density")
      throw InvalidArgument("pair_coeff: density is not a pair coefficient in LAMMPS: give it per "
                            "atom (set type N density/disc RHO for disks)");
    const MaterialKey* k = find_key(key);
    if (k == nullptr)
      throw InvalidArgument("pair_coeff: unknown key '" + key +
                            "'; allowed: " + pair_coefficient_names());
    if (w + 1 >= words.size())
      throw InvalidArgument("pair_coeff " + key + ": the value is missing");
    const double x = parse_number(key, words[w + 1]);
    if (!allowed_value(*k, x))
      throw InvalidArgument("pair_coeff " + key + " = " + words[w + 1] +
                            "; allowed: " + std::string(k->allowed));
    m.*k->field = x;
  }
  return m;
}

} // namespace talus::lammps
