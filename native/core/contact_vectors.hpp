#pragma once
// The laws' contact geometry and force (talus/) with the native engine's Vec2: adapters only,
// the arithmetic is talus/'s.
#include "core/vec2.hpp"
#include "talus/contact_force.hpp"
#include "talus/contact_geometry.hpp"

namespace talus {

inline Vec2 normal_of(const ContactGeometry& g) {
  return {g.normal_x, g.normal_y};
}
/// t = e_z x n.
inline Vec2 tangent_of(const ContactGeometry& g) {
  return perp(normal_of(g));
}
/// The force on i.
inline Vec2 force_of(const ContactForce& c) {
  return {c.force_x, c.force_y};
}

/// pair_geometry with vectors: d = r_i - r_j (minimum image), dist = |d| > 0.
inline ContactGeometry pair_geometry(Vec2 d, double dist, double r_i, double r_j, double m_i,
                                     double m_j, Vec2 v_i, Vec2 v_j, double w_i, double w_j,
                                     bool with_r_eff = true, LeverShares shares = {}) {
  return pair_geometry(d.x, d.y, dist, r_i, r_j, m_i, m_j, v_i.x, v_i.y, v_j.x, v_j.y, w_i, w_j,
                       with_r_eff, shares);
}
/// wall_geometry with vectors: d = r_i - c for the wall's nearest point c moving at v_wall.
inline ContactGeometry wall_geometry(Vec2 d, double dist, double r_i, double m_i, Vec2 v_i,
                                     double w_i, Vec2 v_wall, LeverShares shares = {}) {
  return wall_geometry(d.x, d.y, dist, r_i, m_i, v_i.x, v_i.y, w_i, v_wall.x, v_wall.y, shares);
}

/// What the force stage keeps of a contact, per list entry: the force on i and the torques.
struct PairForce {
  Vec2 force;
  double torque_i = 0.0;
  double torque_j = 0.0;
  PairForce() = default;
  PairForce(const ContactForce& c)
      : force(force_of(c)), torque_i(c.torque_i), torque_j(c.torque_j) {}
};

} // namespace talus
