#pragma once
// The contact forces of a scene of spheres: every touching pair of the list and every sphere on
// a plate, through the contact laws of src/talus in 3D, on any number of threads with the same
// bits. The rows are cut into blocks by the sphere count alone (force_block_rows); a thread takes
// a block at a time and its spheres sum the block's pair contacts in entry order (two computed
// at a time, engine3d/pair_lanes3.hpp), then their plates'; a pair whose second sphere lies in
// a later block keeps its force, which that sphere adds after, in entry order. The order of
// every sum is thus fixed, whatever the threads, and no atomics are needed.
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

/// A touching entry of a block of rows: d = r_i - r_j (j's image), its entry and its first sphere.
struct Touching3 {
  Vec3 d;
  std::uint32_t entry;
  std::uint32_t i;
};

/// What a block's pair or plate contacts met: how many touch, the deepest overlap relative to the
/// smaller radius.
struct ContactTally3 {
  std::size_t contacts = 0;
  double deepest = 0.0;
};

class ForcePass3 {
public:
  /// Sets every sphere's force to its weight (none for a sphere that is not free) plus its
  /// contacts' forces, and its torque to its contacts', sets each plate's force, and advances the
  /// springs of the list by one step `settings.timestep`. `rotation` false (a frictionless scene
  /// whose spheres do not turn: turns_spheres) leaves the torques and the spins' part of the
  /// contacts' velocities out; the torques stay what they were (0). `one_material` true lets
  /// a scene of one material have its pair parameters put in lanes once, not per contact.
  ContactPass3 compute(Scene3& scene, SphereList& list, const PairTable& table,
                       const Settings3& settings, int threads, bool rotation = true,
                       bool one_material = true);

  /// The list's entries changed (a build, a renumbering): which of them touch is taken again from
  /// their springs, and the deferred forces cleared, at the next pass.
  void list_changed() { list_changed_ = true; }

  /// The bytes its buffers take: the deferred forces, the plates', the touching entries' and
  /// which entries touched.
  std::size_t bytes() const;

private:
  // rows whose touching entries are written down, then computed: their entries fit in L1
  static constexpr std::uint32_t stretch_rows = 64;
  template <class N, class T, bool Rotation>
  ContactPass3 compute_with(Scene3& scene, SphereList& list, const PairTable& table,
                            const Settings3& settings, int threads, bool one_material);
  // the plate contacts of spheres [first, last), added to them and kept for the plates' sums
  template <class N, class T, bool Rotation>
  ContactTally3 plate_forces(Scene3& scene, SphereList& list, const PairTable& table,
                             std::uint32_t first, std::uint32_t last, double dt,
                             LeverShares shares);

  // after the list changed: an entry touched if its spring (or rolling spring) is not 0, which
  // holds for the springs the list carries over (a contact with a spring of exactly 0 has none to
  // clear when it ends), and no entry has a deferred force yet
  void take_touching_from_springs(const SphereList& list);

  // per pair entry whose second sphere is in a later block: its force on i, its torque on j
  std::vector<Vec3> deferred_force_, deferred_torque_j_;
  std::vector<std::uint8_t> touched_; // per pair entry: touching at the last pass
  bool list_changed_ = true;
  std::vector<Vec3> plate_force_, plate_torque_; // per sphere-plate entry
  std::vector<std::vector<Touching3>> found_;    // per thread: its block's touching entries
};

/// How many pair contacts the force pass computes at a time: 4 where the 3D engine is built for
/// AVX2 (CMake's TALUS_AVX2), else 2 (SSE2).
int pair_contact_lanes();

/// The elastic energy stored in the contacts (J): the normal laws' and the springs'.
double contact_elastic_energy(const Scene3& scene, const SphereList& list, const PairTable& table,
                              const Settings3& settings);

/// The contact whose overlap is the largest fraction of its smaller radius, in words ("sphere 3
/// overlaps sphere 9 by 0.61 of the smaller radius"), for the guard's message.
std::string deepest_contact(const Scene3& scene, const SphereList& list, const Settings3& settings);

} // namespace talus
