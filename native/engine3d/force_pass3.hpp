#pragma once
// The contact forces of a scene of spheres: every touching pair of the list and every sphere on
// a plate, through the contact laws of src/talus in 3D.
#include <cstddef>
#include <cstdint>

#include "engine3d/scene3.hpp"
#include "engine3d/sphere_list.hpp"
#include "materials/pair_table.hpp"

namespace talus {

/// What a force pass met: the touching contacts and the deepest overlap relative to the
/// smaller radius, with its spheres (j = -1: a plate, then `plate` is its index).
struct ContactPass3 {
  std::size_t contacts = 0;
  double deepest = 0.0;
  std::uint32_t deepest_i = 0;
  std::int64_t deepest_j = -1;
  std::uint32_t deepest_plate = 0;
};

/// Adds the contact forces and torques to every sphere's force and torque, sets each plate's
/// force, and advances the springs of the list by one step `settings.timestep`.
ContactPass3 add_contact_forces(Scene3& scene, SphereList& list, const PairTable& table,
                                const Settings3& settings);

/// The elastic energy stored in the contacts (J): the normal laws' and the springs'.
double contact_elastic_energy(const Scene3& scene, const SphereList& list, const PairTable& table,
                              const Settings3& settings);

} // namespace talus
