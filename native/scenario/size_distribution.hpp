#pragma once
// Grain radii: uniform in a range, a Wentworth class (thesis table 2.1), or a discrete mix.
#include <string_view>
#include <vector>

#include "core/random.hpp"
#include "scenario/scenario.hpp"

namespace talus {

/// A class of the Wentworth scale (thesis table 2.1): mean particle diameter, m.
struct WentworthClass {
  std::string_view name;
  double mean_diameter;
};

/// The classes with a defined mean diameter, from "silt" (0.0625 mm) to "granules" (4 mm).
const std::vector<WentworthClass>& wentworth_classes();

/// Radius bounds of a size spec: [r_min, r_max]. Wentworth classes span mean radius +- 20%
/// (the thesis draws R uniformly between limits around the class' mean, eq. 2.5).
std::pair<double, double> radius_range(const SizeSpec& spec);

/// Draws one radius.
double draw_radius(const SizeSpec& spec, RandomStream& rng);

} // namespace talus
