#pragma once
// Rolling resistance between spheres, or a sphere and a plate, in the 3D engine's terms: the
// scalar contact of the force pass' plates and lanes, and of what looks at the contacts after.
#include <cstddef>

#include "core/vec3.hpp"
#include "engine3d/spheres.hpp"
#include "talus/contact_force.hpp"
#include "talus/contact_geometry_3d.hpp"
#include "talus/rolling_resistance.hpp"

namespace talus {

/// Rolling resistance's torque on i of a contact with rolling spring `theta` (turned into the
/// tangent plane and advanced a step here), against a sphere or plate of spin w_j and rim inertia
/// rim_j (0: a plate, infinitely heavy). None where the pair does not roll with resistance.
template <class N>
Vec3 rolling_torque(const PairParameters& p, const ContactGeometry3& g, double normal_force,
                    const Vec3& w_i, const Vec3& w_j, double rim_i, double rim_j, Vec3& theta,
                    double dt) {
  if (p.rolling_friction == 0.0) return {};
  theta = into_tangent_plane(theta, g.normal);
  return RollingLaw::torque<N>(p, g, not_below_zero(normal_force), rolling_spin(w_i, w_j, g.normal),
                               rolling_inertia(rim_i, rim_j), theta, dt);
}

/// A sphere's inertia about a point of its rim, which rolling resistance's dashpot takes.
inline double rim_of(const Spheres& s, std::size_t i) {
  return rim_inertia(s.inertia[i], s.mass[i], s.radius[i]);
}

/// The elastic energy of a rolling spring as it stands (turned into the tangent plane), J.
template <class N>
double rolling_energy(const PairParameters& p, const ContactGeometry3& g, const Vec3& theta) {
  if (p.rolling_friction == 0.0) return 0.0;
  return RollingLaw::elastic_energy<N>(p, g, into_tangent_plane(theta, g.normal));
}

} // namespace talus
