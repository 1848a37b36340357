#pragma once
// The force and torques of one contact from a normal law N and a tangential law T, for any
// number type (number.hpp): every engine assembles a contact with these lines.
#include "talus/contact_geometry.hpp"
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

} // namespace talus
