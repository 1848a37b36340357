#pragma once
// The touching contacts of a scene of spheres, one at a time with their geometry and parameters:
// for what looks at the contacts without computing the step's forces (the elastic energy, the
// energy ledger's powers, the guard's words). The force pass has its own loops (force_pass3.cpp).
#include <cmath>
#include <cstdint>

#include "engine3d/scene3.hpp"
#include "engine3d/sphere_list.hpp"
#include "materials/pair_table.hpp"
#include "talus/contact_geometry_3d.hpp"

namespace talus {

/// Calls on_plate(i, e, plate, geometry, parameters) for sphere i's touching plates.
template <class OnPlate>
void for_each_plate_contact_of(const Scene3& scene, const SphereList& list, const PairTable& table,
                               LeverShares shares, std::uint32_t i, OnPlate& on_plate) {
  const Spheres& s = scene.spheres;
  for (std::uint32_t e = list.plate_offset[i]; e < list.plate_offset[i + 1]; ++e) {
    const Plane& plate = scene.plates[list.plate[e]];
    const Vec3 touch = closest_point(plate, s.position[i]);
    const Vec3 d = s.position[i] - touch;
    const double dist2 = norm2(d);
    if (dist2 >= s.radius[i] * s.radius[i] || dist2 == 0.0) continue;
    const ContactGeometry3 g =
        wall_geometry(d, std::sqrt(dist2), s.radius[i], s.mass[i], s.velocity[i],
                      s.angular_velocity[i], plate.velocity_at(touch), shares);
    on_plate(i, e, list.plate[e], g, table(s.material[i], plate.material));
  }
}

/// Calls on_pair(i, e, j, geometry, parameters) for the touching pair entries e of sphere i's row.
template <class OnPair>
void for_each_pair_contact_of(const Scene3& scene, const SphereList& list, const PairTable& table,
                              LeverShares shares, std::uint32_t i, OnPair& on_pair) {
  const Spheres& s = scene.spheres;
  for (std::uint32_t e = list.row_offset[i]; e < list.row_offset[i + 1]; ++e) {
    const std::uint32_t j = list.neighbour[e];
    const Vec3 d = s.position[i] - (s.position[j] + list.offset(e, scene.domain));
    const double reach = s.radius[i] + s.radius[j];
    const double dist2 = norm2(d);
    if (dist2 >= reach * reach || dist2 == 0.0) continue;
    const ContactGeometry3 g =
        pair_geometry(d, std::sqrt(dist2), s.radius[i], s.radius[j], s.mass[i], s.mass[j],
                      s.velocity[i], s.velocity[j] + list.image_velocity(e, scene.domain),
                      s.angular_velocity[i], s.angular_velocity[j], true, shares);
    on_pair(i, e, j, g, table(s.material[i], s.material[j]));
  }
}

/// Calls on_pair(i, e, j, geometry, parameters) for every touching pair entry e of the list, in
/// row order, then on_plate(i, e, plate, geometry, parameters) for sphere i's touching plates.
template <class OnPair, class OnPlate>
void for_each_contact3(const Scene3& scene, const SphereList& list, const PairTable& table,
                       LeverShares shares, OnPair&& on_pair, OnPlate&& on_plate) {
  for (std::uint32_t i = 0; i < scene.spheres.size(); ++i) {
    for_each_pair_contact_of(scene, list, table, shares, i, on_pair);
    for_each_plate_contact_of(scene, list, table, shares, i, on_plate);
  }
}

/// Calls on_plate(i, e, plate, geometry, parameters) for every touching plate of every sphere,
/// sphere after sphere.
template <class OnPlate>
void for_each_plate_contact3(const Scene3& scene, const SphereList& list, const PairTable& table,
                             LeverShares shares, OnPlate&& on_plate) {
  for (std::uint32_t i = 0; i < scene.spheres.size(); ++i)
    for_each_plate_contact_of(scene, list, table, shares, i, on_plate);
}

} // namespace talus
