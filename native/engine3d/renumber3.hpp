#pragma once
// Renumbering the spheres in the order of the cells they lie in, so that a sphere's neighbours
// lie near it in memory as the flow mixes them (the 2D engine's sort_interval, for spheres).
#include <cstdint>
#include <vector>

#include "engine3d/gear3.hpp"
#include "engine3d/sphere_list.hpp"

namespace talus {

/// Puts the sphere of old index old_of_new[k] at index k, with every field of it, its Gear
/// derivatives and its list entries: a pair whose order turns round keeps its springs
/// negated (they are i's displacement against j) and its periodic image reversed; the rows
/// ascend again. The list stays valid (its build positions follow), so it is not rebuilt.
void renumber_spheres(Spheres& s, SphereList& list, GearState3& gear,
                      const std::vector<std::uint32_t>& old_of_new);

} // namespace talus
