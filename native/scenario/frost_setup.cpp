#include "scenario/frost_setup.hpp"

#include <algorithm>
#include <vector>

#include "talus/error.hpp"

namespace talus {

FrostFrontParameters front_parameters(const Scenario& s, const Particles& p, const Rect& bounds) {
  const FrostSection& f = s.frost;
  std::vector<double> radii;
  for (std::size_t i = 0; i < p.size(); ++i) // free grains, or held by a frost being resumed
    if (p.kind[i] != Kind::fixed) radii.push_back(p.radius[i]);
  if (radii.empty()) throw InvalidArgument("frost: there are no free grains");
  std::sort(radii.begin(), radii.end());
  FrostFrontParameters q;
  q.permafrost_depth = f.permafrost_depth;
  q.heave_strain = f.heave_strain;
  q.conductivity_ratio = f.conductivity_ratio;
  q.stone_water = f.stone_water;
  q.ice_content = f.ice_content;
  q.stone_radius = f.stone_radius > 0.0 ? f.stone_radius : 1.5 * radii[radii.size() / 2];
  q.column_width = f.column_width > 0.0 ? f.column_width : 2.0 * radii.back();
  q.crust_length = f.crust_length > 0.0 ? f.crust_length : q.column_width;
  q.freeze_time = f.freeze_time;
  q.thaw_time = f.thaw_time;
  q.frost_pull = f.frost_pull;
  for (std::size_t m = 0; m < s.materials.size(); ++m)
    if (!f.thawed_material.empty() && s.materials[m].name == f.thawed_material)
      q.thawed_material = static_cast<int>(m);
  q.x_min = bounds.lo.x;
  q.x_max = bounds.hi.x;
  return q;
}

} // namespace talus
