#pragma once
// The force and torques of one contact from a normal law N and a tangential law T, for any
// number type (number.hpp), of disks in 2D or of spheres in 3D: every engine assembles a contact
// with these lines.
#include "talus/contact_geometry.hpp"
#include "talus/contact_geometry_3d.hpp"
#include "talus/pair_parameters.hpp"

namespace talus {

/// Force and torques of a contact: the force on i (j gets the opposite), torques on i and on j,
/// and the normal force F_n (N): >= 0 but for the pull of the linear law's classic dashpot.
template <class R> struct ContactForceOf {
  R force_x{}, force_y{};
  R torque_i{}, torque_j{};
  R normal_force{};
};
using ContactForce = ContactForceOf<double>;

/// The contact's force for the law pair (N, T); `history` is its tangential spring (T's
/// history, untouched by a law without one), advanced by the timestep dt.
template <class N, class T, class R>
inline ContactForceOf<R> contact_force(const PairParametersOf<R>& p, const ContactGeometryOf<R>& g,
                                       R& history, double dt) {
  ContactForceOf<R> c;
  c.normal_force = N::force(p, g);
  // a pull (the classic linear dashpot's) gives no friction
  R limit_force = c.normal_force;
  if constexpr (N::can_pull) limit_force = not_below_zero(limit_force);
  const R ft = T::template force<N>(p, g, limit_force, history, dt);
  c.force_x = c.normal_force * g.normal_x + ft * -g.normal_y;
  c.force_y = c.normal_force * g.normal_y + ft * g.normal_x;
  c.torque_i = -g.arm_i * ft;
  c.torque_j = -g.arm_j * ft;
  return c;
}

/// Force and torques of a contact of spheres: the force on i (j gets the opposite), the torques
/// on i and on j, and the normal force F_n.
template <class R> struct ContactForce3Of {
  Vec3Of<R> force;
  Vec3Of<R> torque_i, torque_j;
  R normal_force{};
};
using ContactForce3 = ContactForce3Of<double>;

/// A contact's vector history (a tangential spring, a rolling angle) turned into the tangent
/// plane of the normal n as the contact turns: its part in the plane, rescaled to its length,
/// as LAMMPS' granular pair styles and LIGGGHTS keep theirs. The spring keeps its energy; the
/// turn itself does no work. A history along n (a turn of a quarter circle in one step, never
/// in a resolved contact) is lost.
template <class R> Vec3Of<R> into_tangent_plane(const Vec3Of<R>& h, const Vec3Of<R>& n) {
  const R before = magnitude(h);
  const Vec3Of<R> in = h - dot(h, n) * n;
  const R after = magnitude(in);
  return select(after > 0.0, (before / after) * in, in);
}

/// The contact's force for the law pair (N, T) in 3D: the same laws as in 2D, the tangential
/// ones on vectors in the tangent plane. `history`, the tangential spring, is turned into the
/// contact's tangent plane first. The torques -a (n x F_t) are, in a plane, the 2D -a F_t.
template <class N, class T, class R>
inline ContactForce3Of<R> contact_force(const PairParametersOf<R>& p,
                                        const ContactGeometry3Of<R>& g, Vec3Of<R>& history,
                                        double dt) {
  ContactForce3Of<R> c;
  c.normal_force = N::force(p, g);
  R limit_force = c.normal_force;
  if constexpr (N::can_pull) limit_force = not_below_zero(limit_force);
  if constexpr (T::has_history) history = into_tangent_plane(history, g.normal);
  const Vec3Of<R> ft = T::template force<N>(p, g, limit_force, history, dt);
  c.force = c.normal_force * g.normal + ft;
  const Vec3Of<R> turn = cross(g.normal, ft);
  c.torque_i = -g.arm_i * turn;
  c.torque_j = -g.arm_j * turn;
  return c;
}

/// Elastic energy stored in one contact: normal part plus 1/2 k_t s^2 for the spring laws.
template <class N, class T>
inline double contact_elastic_energy(const PairParameters& p, const ContactGeometry& g,
                                     double history) {
  double e = N::elastic_energy(p, g);
  if constexpr (T::has_history) {
    const double kt = T::stiffness(p, g, N::stiffness(p, g));
    e += 0.5 * kt * history * history;
  }
  return e;
}
/// The same for spheres in 3D: 1/2 k_t |s|^2 of the spring's vector.
template <class N, class T>
inline double contact_elastic_energy(const PairParameters& p, const ContactGeometry3& g,
                                     const Vec3& history) {
  double e = N::elastic_energy(p, g);
  if constexpr (T::has_history) {
    const double kt = T::stiffness(p, g, N::stiffness(p, g));
    e += 0.5 * kt * dot(history, history);
  }
  return e;
}

} // namespace talus
