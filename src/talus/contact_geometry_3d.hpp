#pragma once
// The geometry and kinematics of a contact between spheres in three dimensions, beside the 2D
// one (contact_geometry.hpp), with the same conventions and the same fields but the normal, the
// tangential velocity and the spins as vectors. The normal laws read only the scalars (overlap,
// its rate, r_eff, m_eff), so they serve both as they are; the tangential and rolling laws take
// the vectors through the operations of vector3.hpp.
#include "talus/contact_geometry.hpp"
#include "talus/vector3.hpp"

namespace talus {

/// One touching pair (i, j) of spheres, j possibly a wall. n points from j to i; the overlap
/// xi = R_i + R_j - |r_i - r_j| > 0; the lever arms a_i = R_i - xi/2 and a_j = R_j - xi/2 (or as
/// LeverShares say); v_n the normal component of the velocity of i's contact point relative to
/// j's (v_n < 0: approaching), v_t its part in the tangent plane (perpendicular to n).
template <class R> struct ContactGeometry3Of {
  Vec3Of<R> normal;
  R overlap{};
  R r_eff{};
  R m_eff{};
  R arm_i{};
  R arm_j{};
  R v_normal{};
  Vec3Of<R> v_tangent;

  /// Rate of change of the overlap, d xi / dt = -v_n.
  R overlap_rate() const { return -v_normal; }
};
using ContactGeometry3 = ContactGeometry3Of<double>;

/// The kinematics shared by a pair and a wall: `dv` the centres' relative velocity, `spin_part`
/// = reach_i w_i + reach_j w_j, whose cross product with n is the spins' part of the contact
/// points' relative velocity (i's contact point sits at -reach_i n from its centre, j's at
/// +reach_j n: w_i x (-reach_i n) - w_j x (reach_j n) = -(spin_part x n)).
template <class R>
void set_velocities(ContactGeometry3Of<R>& g, const Vec3Of<R>& dv, const Vec3Of<R>& spin_part) {
  const Vec3Of<R> relative = dv - cross(spin_part, g.normal);
  g.v_normal = dot(relative, g.normal);
  g.v_tangent = relative - g.v_normal * g.normal;
}

/// Geometry of a sphere pair: d = r_i - r_j (minimum image), dist = |d| > 0, v the velocities,
/// w the spins. `with_r_eff` and `shares`: as pair_geometry's (contact_geometry.hpp).
template <class R>
ContactGeometry3Of<R> pair_geometry(const Vec3Of<R>& d, R dist, R r_i, R r_j, R m_i, R m_j,
                                    const Vec3Of<R>& v_i, const Vec3Of<R>& v_j,
                                    const Vec3Of<R>& w_i, const Vec3Of<R>& w_j,
                                    bool with_r_eff = true, LeverShares shares = {}) {
  ContactGeometry3Of<R> g;
  const R inverse = 1.0 / dist;
  g.normal = inverse * d;
  const Reaches<R> reach = set_pair_scalars(g, dist, r_i, r_j, m_i, m_j, with_r_eff, shares);
  set_velocities(g, v_i - v_j, reach.i * w_i + reach.j * w_j);
  return g;
}

/// Geometry of a sphere against the nearest point c of a wall: d = r_i - c, dist = |d| > 0, the
/// wall's velocity at c. The wall has infinite radius and mass: r_eff = R, m_eff = m.
template <class R>
ContactGeometry3Of<R> wall_geometry(const Vec3Of<R>& d, R dist, R r_i, R m_i, const Vec3Of<R>& v_i,
                                    const Vec3Of<R>& w_i, const Vec3Of<R>& v_wall,
                                    LeverShares shares = {}) {
  ContactGeometry3Of<R> g;
  g.normal = d / dist;
  set_velocities(g, v_i - v_wall, set_wall_scalars(g, dist, r_i, m_i, shares) * w_i);
  return g;
}

} // namespace talus
