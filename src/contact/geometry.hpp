#pragma once
// The geometry and kinematics of one contact, shared by every contact law.
#include "core/vec2.hpp"

namespace talus {

/// One touching pair (i, j), j possibly a wall. Conventions: n points from j to i; t = e_z x n;
/// the overlap xi = R_i + R_j - |r_i - r_j| > 0; the contact point lies mid-overlap, at lever
/// arms a_i = R_i - xi/2 from i and a_j = R_j - xi/2 from j (so a_i + a_j = |r_i - r_j| and
/// torques conserve angular momentum exactly); v_n and v_t are the normal and tangential
/// components of the velocity of i's contact point relative to j's (v_n < 0: approaching).
struct ContactGeometry {
  Vec2 normal;
  double overlap = 0.0;
  double r_eff = 0.0;
  double m_eff = 0.0;
  double arm_i = 0.0;
  double arm_j = 0.0;
  double v_normal = 0.0;
  double v_tangent = 0.0;

  Vec2 tangent() const { return perp(normal); }
  /// Rate of change of the overlap, d xi / dt = -v_n.
  double overlap_rate() const { return -v_normal; }
};

/// Force and torques of one contact: the force on i (j gets -force), torques on i and on j.
struct ContactForce {
  Vec2 force;
  double torque_i = 0.0;
  double torque_j = 0.0;
  double normal_force = 0.0; ///< F_n >= 0, N
};

/// What the force stage keeps of a contact, per list entry (the lean form of ContactForce).
struct PairForce {
  Vec2 force;
  double torque_i = 0.0;
  double torque_j = 0.0;
  PairForce() = default;
  PairForce(const ContactForce& c) : force(c.force), torque_i(c.torque_i), torque_j(c.torque_j) {}
};

/// Geometry of a particle-particle pair; d = r_i - r_j (minimum image), dist = |d| > 0.
/// `with_r_eff` = false leaves r_eff at 0 for laws that do not use it (saves a division).
inline ContactGeometry pair_geometry(Vec2 d, double dist, double r_i, double r_j, double m_i,
                                     double m_j, Vec2 v_i, Vec2 v_j, double w_i, double w_j,
                                     bool with_r_eff = true) {
  ContactGeometry g;
  g.normal = d * (1.0 / dist);
  g.overlap = r_i + r_j - dist;
  g.r_eff = with_r_eff ? r_i * r_j / (r_i + r_j) : 0.0;
  g.m_eff = m_i * m_j / (m_i + m_j);
  g.arm_i = r_i - 0.5 * g.overlap;
  g.arm_j = r_j - 0.5 * g.overlap;
  const Vec2 dv = v_i - v_j;
  g.v_normal = dot(dv, g.normal);
  g.v_tangent = dot(dv, perp(g.normal)) - (w_i * g.arm_i + w_j * g.arm_j);
  return g;
}

/// Geometry of a particle against a wall point c (nearest point of the wall), wall velocity
/// v_wall at c. The wall has infinite radius and mass: r_eff = R, m_eff = m.
inline ContactGeometry wall_geometry(Vec2 d, double dist, double r_i, double m_i, Vec2 v_i,
                                     double w_i, Vec2 v_wall) {
  ContactGeometry g;
  g.normal = d / dist;
  g.overlap = r_i - dist;
  g.r_eff = r_i;
  g.m_eff = m_i;
  g.arm_i = r_i - 0.5 * g.overlap;
  g.arm_j = 0.0;
  const Vec2 dv = v_i - v_wall;
  g.v_normal = dot(dv, g.normal);
  g.v_tangent = dot(dv, perp(g.normal)) - w_i * g.arm_i;
  return g;
}

} // namespace talus
