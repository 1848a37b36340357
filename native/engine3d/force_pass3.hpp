#pragma once
// The contact forces of a scene of spheres: every touching pair of the list and every sphere on
// a plate, through the contact laws of src/talus in 3D, on any number of threads with the same
// bits: each entry's force is computed once (rows side by side), then each sphere sums its
// entries' forces in a fixed order (its row, then the entries where it is second, then its
// plates), never by atomics.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine3d/scene3.hpp"
#include "engine3d/sphere_list.hpp"
#include "materials/pair_table.hpp"

namespace talus {

/// What a force pass met: the touching contacts (of them, those on plates) and the deepest
/// overlap relative to the smaller radius.
struct ContactPass3 {
  std::size_t contacts = 0;
  std::size_t on_plates = 0;
  double deepest = 0.0;
};

class ForcePass3 {
public:
  /// Adds the contact forces and torques to every sphere's force and torque, sets each plate's
  /// force, and advances the springs of the list by one step `settings.timestep`.
  ContactPass3 add(Scene3& scene, SphereList& list, const PairTable& table,
                   const Settings3& settings, int threads);

  /// The bytes its per-entry forces take.
  std::size_t bytes() const;

private:
  std::vector<Vec3> force_, torque_i_, torque_j_; // per pair entry
  std::vector<Vec3> plate_force_, plate_torque_;  // per sphere-plate entry
};

/// The elastic energy stored in the contacts (J): the normal laws' and the springs'.
double contact_elastic_energy(const Scene3& scene, const SphereList& list, const PairTable& table,
                              const Settings3& settings);

/// The contact whose overlap is the largest fraction of its smaller radius, in words ("sphere 3
/// overlaps sphere 9 by 0.61 of the smaller radius"), for the guard's message.
std::string deepest_contact(const Scene3& scene, const SphereList& list, const Settings3& settings);

} // namespace talus
