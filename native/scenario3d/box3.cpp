#include "scenario3d/box3.hpp"

#include <array>

namespace talus {

std::vector<BoxSide> box3_sides(const Box3Section& g) {
  constexpr std::array<std::array<const char*, 2>, 3> names{
      {{"left", "right"}, {"front", "back"}, {"floor", "lid"}}};
  std::vector<BoxSide> out;
  for (int k = 0; k < 3; ++k) {
    const auto axis = static_cast<std::size_t>(k);
    if (g.periodic[axis]) continue;
    Vec3 normal{};
    component(normal, k) = 1.0;
    out.push_back({names[axis][0], g.lo, normal});
    if (k == 2 && g.open_top) continue;
    out.push_back({names[axis][1], g.hi, -normal});
  }
  return out;
}

std::vector<std::uint32_t> box3_target(const Box3Section& g, const std::string& target) {
  const std::vector<BoxSide> sides = box3_sides(g);
  std::vector<std::uint32_t> out;
  for (std::uint32_t w = 0; w < sides.size(); ++w)
    if (target == "walls" || sides[w].name == target) out.push_back(w);
  return out;
}

std::string box3_targets(const Box3Section& g) {
  std::string out = "walls";
  for (const BoxSide& side : box3_sides(g)) out += ", " + side.name;
  return out;
}

} // namespace talus
