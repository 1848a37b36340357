#include "scenario/size_distribution.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "scenario/file/toml_reader.hpp"

namespace talus {

const std::vector<WentworthClass>& wentworth_classes() {
  static const std::vector<WentworthClass> classes = {
      {"silt", 0.0625e-3},     {"very fine sand", 0.125e-3}, {"fine sand", 0.25e-3},
      {"medium sand", 0.5e-3}, {"coarse sand", 1.0e-3},      {"very coarse sand", 2.0e-3},
      {"granules", 4.0e-3}};
  return classes;
}

namespace {
constexpr double wentworth_spread = 0.2; // relative half-width of a class' radius range

double wentworth_mean_radius(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  std::replace(lower.begin(), lower.end(), '_', ' ');
  std::string names;
  for (const auto& c : wentworth_classes()) {
    if (c.name == lower) return 0.5 * c.mean_diameter;
    names += (names.empty() ? "" : ", ") + std::string(c.name);
  }
  throw ScenarioError("key 'particles.size.class': unknown Wentworth class '" + name +
                      "'; allowed: " + names);
}
} // namespace

std::pair<double, double> radius_range(const SizeSpec& spec) {
  if (spec.distribution == "wentworth") {
    const double r = wentworth_mean_radius(spec.wentworth_class);
    return {r * (1.0 - wentworth_spread), r * (1.0 + wentworth_spread)};
  }
  if (spec.distribution == "discrete") {
    const auto [lo, hi] = std::minmax_element(spec.radii.begin(), spec.radii.end());
    return {*lo, *hi};
  }
  return {spec.mean_radius - spec.spread, spec.mean_radius + spec.spread};
}

double draw_radius(const SizeSpec& spec, RandomStream& rng) {
  if (spec.distribution == "discrete") {
    double u = rng.uniform();
    for (std::size_t k = 0; k < spec.radii.size(); ++k) {
      if (u < spec.fractions[k]) return spec.radii[k];
      u -= spec.fractions[k];
    }
    return spec.radii.back();
  }
  const auto [lo, hi] = radius_range(spec);
  return lo + rng.uniform() * (hi - lo); // thesis eq. 2.5
}

} // namespace talus
