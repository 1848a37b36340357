#include "engine3d/force_pass3.hpp"

#include <algorithm>
#include <cmath>

#include "talus/contact_force.hpp"
#include "talus/contact_geometry_3d.hpp"

namespace talus {

namespace {

// Calls f(geometry, parameters, spring) for every touching sphere pair (i, j, entry) and then
// every touching sphere-plate pair (i, plate, entry); a spring of a pair no longer touching is
// cleared.
template <class Pair, class OnPlate, class S, class L>
void for_each_contact(S& scene, L& list, const PairTable& table, const Settings3& settings,
                      Pair&& on_pair, OnPlate&& on_plate) {
  const Spheres& s = scene.spheres;
  const LeverShares shares = lever_shares(settings.lever_arm);
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (std::uint32_t e = list.row_offset[i]; e < list.row_offset[i + 1]; ++e) {
      const std::uint32_t j = list.neighbour[e];
      const Vec3 d = s.position[i] - (s.position[j] + list.offset(e, scene.domain));
      const double reach = s.radius[i] + s.radius[j];
      const double dist2 = norm2(d);
      if (dist2 >= reach * reach || dist2 == 0.0) {
        if constexpr (!std::is_const_v<L>) list.spring[e] = {};
        continue;
      }
      const ContactGeometry3 g = pair_geometry(
          d, std::sqrt(dist2), s.radius[i], s.radius[j], s.mass[i], s.mass[j], s.velocity[i],
          s.velocity[j], s.angular_velocity[i], s.angular_velocity[j], true, shares);
      on_pair(i, j, g, table(s.material[i], s.material[j]), list.spring[e]);
    }
    for (std::uint32_t e = list.plate_offset[i]; e < list.plate_offset[i + 1]; ++e) {
      const auto& plate = scene.plates[list.plate[e]];
      const Vec3 d = s.position[i] - closest_point(plate, s.position[i]);
      const double dist2 = norm2(d);
      if (dist2 >= s.radius[i] * s.radius[i] || dist2 == 0.0) {
        if constexpr (!std::is_const_v<L>) list.plate_spring[e] = {};
        continue;
      }
      const ContactGeometry3 g =
          wall_geometry(d, std::sqrt(dist2), s.radius[i], s.mass[i], s.velocity[i],
                        s.angular_velocity[i], plate.velocity, shares);
      on_plate(i, list.plate[e], g, table(s.material[i], plate.material), list.plate_spring[e]);
    }
  }
}

template <class N, class T>
ContactPass3 add_forces(Scene3& scene, SphereList& list, const PairTable& table,
                        const Settings3& settings) {
  Spheres& s = scene.spheres;
  const double dt = settings.timestep;
  ContactPass3 pass;
  for (Plane& p : scene.plates) p.force = {};
  const auto note = [&](double overlap, double radius, std::uint32_t i, std::int64_t j,
                        std::uint32_t plate) {
    ++pass.contacts;
    if (!(overlap / radius <= pass.deepest)) pass = {pass.contacts, overlap / radius, i, j, plate};
  };
  for_each_contact(
      scene, list, table, settings,
      [&](std::size_t i, std::uint32_t j, const ContactGeometry3& g, const PairParameters& p,
          Vec3& spring) {
        const ContactForce3 c = contact_force<N, T>(p, g, spring, dt);
        s.force[i] += c.force;
        s.force[j] -= c.force;
        s.torque[i] += c.torque_i;
        s.torque[j] += c.torque_j;
        note(g.overlap, std::min(s.radius[i], s.radius[j]), static_cast<std::uint32_t>(i), j, 0);
      },
      [&](std::size_t i, std::uint32_t w, const ContactGeometry3& g, const PairParameters& p,
          Vec3& spring) {
        const ContactForce3 c = contact_force<N, T>(p, g, spring, dt);
        s.force[i] += c.force;
        s.torque[i] += c.torque_i;
        scene.plates[w].force -= c.force;
        note(g.overlap, s.radius[i], static_cast<std::uint32_t>(i), -1, w);
      });
  return pass;
}

} // namespace

ContactPass3 add_contact_forces(Scene3& scene, SphereList& list, const PairTable& table,
                                const Settings3& settings) {
  return with_contact_law(settings.normal_law, settings.tangential_law, [&]<class N, class T>() {
    return add_forces<N, T>(scene, list, table, settings);
  });
}

double contact_elastic_energy(const Scene3& scene, const SphereList& list, const PairTable& table,
                              const Settings3& settings) {
  return with_contact_law(settings.normal_law, settings.tangential_law, [&]<class N, class T>() {
    double e = 0.0;
    const auto add = [&](std::size_t, std::uint32_t, const ContactGeometry3& g,
                         const PairParameters& p, const Vec3& spring) {
      e += contact_elastic_energy<N, T>(p, g, into_tangent_plane(spring, g.normal));
    };
    for_each_contact(scene, list, table, settings, add, add);
    return e;
  });
}

} // namespace talus
