#pragma once
// The geometry and kinematics of a contact, shared by every contact law and every engine. One
// definition for any number type R (number.hpp): one contact with double, several side by side
// with a SIMD type; each element rounds as the double code does, so both give the same bits.
#include <cstdint>
#include <string>
#include <string_view>

#include "talus/error.hpp"
#include "talus/number.hpp"

namespace talus {

/// Where a contact's lever arms reach, for the spin's part of the tangential velocity and for
/// the torques: to the contact point mid-overlap, a_i = R_i - xi/2 (the default: a_i + a_j =
/// |r_i - r_j|, so the torques conserve angular momentum exactly); to the radius, a_i = R_i, as
/// LAMMPS' gran/* pair styles take it (then the pair's torques conserve it only to O(xi/R)); or
/// `granular`, as LAMMPS' pair_style granular and fix wall/gran granular take them: the spin's
/// velocity at the radius, the torques at the contact point.
enum class LeverArm : std::uint8_t { contact_point = 0, radius = 1, granular = 2 };

/// The shares of the overlap the lever arms are short of the radius: a_i = R_i - share xi, for
/// the torques and for the spin's part of the contact point's velocity.
struct LeverShares {
  double torque = 0.5;
  double velocity = 0.5;
};
/// The convention's name in scenario files (simulation.lever_arm).
inline const char* to_string(LeverArm arm) {
  switch (arm) {
  case LeverArm::radius:
    return "radius";
  case LeverArm::granular:
    return "granular";
  case LeverArm::contact_point:
    break;
  }
  return "contact_point";
}
/// The convention of a name from to_string; throws InvalidArgument with the allowed names.
inline LeverArm parse_lever_arm(std::string_view name) {
  for (const LeverArm arm : {LeverArm::contact_point, LeverArm::radius, LeverArm::granular})
    if (name == to_string(arm)) return arm;
  throw InvalidArgument("unknown lever arm '" + std::string(name) +
                        "'; allowed: contact_point, radius, granular");
}

inline LeverShares lever_shares(LeverArm arm) {
  switch (arm) {
  case LeverArm::radius:
    return {0.0, 0.0};
  case LeverArm::granular:
    return {0.5, 0.0};
  case LeverArm::contact_point:
    break;
  }
  return {};
}

/// One touching pair (i, j), j possibly a wall. Conventions: n points from j to i; t = e_z x n
/// = (-n_y, n_x); the overlap xi = R_i + R_j - |r_i - r_j| > 0; the contact point lies
/// mid-overlap, at lever arms a_i = R_i - xi/2 from i and a_j = R_j - xi/2 from j (LeverArm:
/// or at the radii, as LAMMPS takes them); v_n and v_t are the normal and
/// tangential components of the velocity of i's contact point relative to j's (v_n < 0:
/// approaching).
template <class R> struct ContactGeometryOf {
  R normal_x{}, normal_y{};
  R overlap{};
  R r_eff{};
  R m_eff{};
  R arm_i{};
  R arm_j{};
  R v_normal{};
  R v_tangent{};

  /// Rate of change of the overlap, d xi / dt = -v_n.
  R overlap_rate() const { return -v_normal; }
};
using ContactGeometry = ContactGeometryOf<double>;

/// The lever arms' reaches for the spins' part of the contact points' velocity.
template <class R> struct Reaches { R i{}, j{}; };

/// The scalars of a pair's contact, the same in 2D and 3D (G: ContactGeometryOf or
/// ContactGeometry3Of): the overlap, r_eff (0 without `with_r_eff`), m_eff and the lever arms;
/// returns the reaches the spins' velocity takes.
template <class G, class R>
Reaches<R> set_pair_scalars(G& g, R dist, R r_i, R r_j, R m_i, R m_j, bool with_r_eff,
                            LeverShares shares) {
  g.overlap = r_i + r_j - dist;
  g.r_eff = with_r_eff ? r_i * r_j / (r_i + r_j) : R{};
  g.m_eff = m_i * m_j / (m_i + m_j);
  g.arm_i = r_i - shares.torque * g.overlap;
  g.arm_j = r_j - shares.torque * g.overlap;
  // the same arms, to the bit, where the convention takes the velocity there too
  return {r_i - shares.velocity * g.overlap, r_j - shares.velocity * g.overlap};
}

/// The same against a wall, of infinite radius and mass: r_eff = R, m_eff = m, no arm for j.
template <class G, class R> R set_wall_scalars(G& g, R dist, R r_i, R m_i, LeverShares shares) {
  g.overlap = r_i - dist;
  g.r_eff = r_i;
  g.m_eff = m_i;
  g.arm_i = r_i - shares.torque * g.overlap;
  g.arm_j = R{};
  return r_i - shares.velocity * g.overlap;
}

/// Geometry of a particle-particle pair: d = r_i - r_j (minimum image), dist = |d| > 0, the
/// velocities by components, w the spins. `with_r_eff` = false leaves r_eff at 0 for laws that
/// do not use it (it saves a division). `shares`: the lever-arm convention's (lever_shares).
template <class R>
ContactGeometryOf<R> pair_geometry(R dx, R dy, R dist, R r_i, R r_j, R m_i, R m_j, R vx_i, R vy_i,
                                   R vx_j, R vy_j, R w_i, R w_j, bool with_r_eff = true,
                                   LeverShares shares = {}) {
  ContactGeometryOf<R> g;
  const R inverse = 1.0 / dist;
  g.normal_x = inverse * dx;
  g.normal_y = inverse * dy;
  const Reaches<R> reach = set_pair_scalars(g, dist, r_i, r_j, m_i, m_j, with_r_eff, shares);
  const R dvx = vx_i - vx_j, dvy = vy_i - vy_j;
  g.v_normal = dvx * g.normal_x + dvy * g.normal_y;
  g.v_tangent = (dvx * -g.normal_y + dvy * g.normal_x) - (w_i * reach.i + w_j * reach.j);
  return g;
}

/// Geometry of a particle against the nearest point c of a wall: d = r_i - c, dist = |d| > 0, the
/// wall's velocity (vx_wall, vy_wall) at c. The wall has infinite radius and mass: r_eff = R,
/// m_eff = m. `shares`: as in pair_geometry.
template <class R>
ContactGeometryOf<R> wall_geometry(R dx, R dy, R dist, R r_i, R m_i, R vx_i, R vy_i, R w_i,
                                   R vx_wall, R vy_wall, LeverShares shares = {}) {
  ContactGeometryOf<R> g;
  g.normal_x = dx / dist;
  g.normal_y = dy / dist;
  const R reach_i = set_wall_scalars(g, dist, r_i, m_i, shares);
  const R dvx = vx_i - vx_wall, dvy = vy_i - vy_wall;
  g.v_normal = dvx * g.normal_x + dvy * g.normal_y;
  g.v_tangent = (dvx * -g.normal_y + dvy * g.normal_x) - w_i * reach_i;
  return g;
}

} // namespace talus
