#pragma once
// The force of every touching contact of a 3D scene as the laws give it in the state as it is
// (the springs as the last step left them, never advanced by looking): for the stress, the
// snapshots' contacts and the fields coarse-grained from them.
#include <cstdint>
#include <vector>

#include "engine3d/contact_visit3.hpp"
#include "engine3d/simulation3.hpp"
#include "talus/law_table.hpp"

namespace talus {

/// Calls on_pair(i, j, geometry, force on i) for every touching pair and on_plate(i, plate,
/// geometry, force on i) for every touching plate, in the list's order.
template <class OnPair, class OnPlate>
void visit_contact_forces3(const Simulation3& sim, OnPair&& on_pair, OnPlate&& on_plate) {
  const Scene3& scene = sim.scene();
  const SphereList& list = sim.list();
  const Settings3& c = sim.settings();
  with_contact_law(c.normal_law, c.tangential_law, [&]<class N, class T>() {
    for_each_contact3(
        scene, list, sim.table(), lever_shares(c.lever_arm),
        [&](std::uint32_t i, std::uint32_t e, std::uint32_t j, const ContactGeometry3& g,
            const PairParameters& p) {
          Vec3 history = list.spring_at(e); // a copy: looking must not advance it
          on_pair(i, j, g, contact_force<N, T>(p, g, history, 0.0).force);
        },
        [&](std::uint32_t i, std::uint32_t e, std::uint32_t plate, const ContactGeometry3& g,
            const PairParameters& p) {
          Vec3 history = list.plate_spring_at(e);
          on_plate(i, plate, g, contact_force<N, T>(p, g, history, 0.0).force);
        });
  });
}

/// One touching contact as the snapshots record it.
struct ContactRecord3 {
  std::uint32_t i = 0; ///< the sphere (an index of the scene)
  std::int64_t j = -1; ///< the partner sphere, or -1 - the plate's index
  Vec3 from;           ///< m: i's centre
  Vec3 to;             ///< m: the partner's centre (its image beside i), or the plate's point
  Vec3 point;          ///< m: the contact point: the middle of the overlap, or the plate's point
  Vec3 force;          ///< N: the contact's force on i (on the partner, its opposite)
  double normal_force = 0.0;     ///< N: along the normal, positive pushing apart
  double tangential_force = 0.0; ///< N: the magnitude of the rest
  double overlap = 0.0;          ///< m
};

/// The touching contacts of the scene, pairs and plates in the list's order.
std::vector<ContactRecord3> contact_records3(const Simulation3& sim);

} // namespace talus
