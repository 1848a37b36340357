#pragma once
// Two particle-particle contacts computed side by side, one per lane (core/lanes.hpp): the
// force stage's form of pair_geometry and contact_force. The laws are the same code as for one
// contact; the geometry and the assembly below repeat the scalar lines of contact/geometry.hpp and
// contact/contact_law.hpp operation for operation, so each lane gives the scalar result to the
// bit (tests/unit/test_contact_lanes.cpp checks every law pair).
#include "core/lanes.hpp"
#include "materials/pair_table.hpp"

namespace talus {

/// The parameters of two contacts' material pairs, lane by lane. Built inline, so that the
/// fields a law does not read are never loaded.
struct PairLanes {
  Lanes normal_stiffness, damping_rate, damping_sqrt_coeff, tangential_stiffness_ratio,
      tangential_damping, friction, effective_young, effective_shear, hertz_damping;

  PairLanes(const PairParameters& a, const PairParameters& b)
      : normal_stiffness{a.normal_stiffness, b.normal_stiffness},
        damping_rate{a.damping_rate, b.damping_rate}, damping_sqrt_coeff{a.damping_sqrt_coeff,
                                                                         b.damping_sqrt_coeff},
        tangential_stiffness_ratio{a.tangential_stiffness_ratio, b.tangential_stiffness_ratio},
        tangential_damping{a.tangential_damping, b.tangential_damping},
        friction{a.friction, b.friction}, effective_young{a.effective_young, b.effective_young},
        effective_shear{a.effective_shear, b.effective_shear}, hertz_damping{a.hertz_damping,
                                                                             b.hertz_damping} {}

  /// PairParameters::normal_dashpot, lane by lane.
  Lanes normal_dashpot(Lanes m_eff) const {
    const Lanes rate_part = damping_rate * m_eff;
    if (damping_sqrt_coeff[0] == 0.0 && damping_sqrt_coeff[1] == 0.0) return rate_part;
    return select(damping_sqrt_coeff == 0.0, rate_part,
                  rate_part + damping_sqrt_coeff * square_root(m_eff));
  }
};

/// ContactGeometry of two contacts, lane by lane; the normal by its components.
struct ContactLanes {
  Lanes normal_x, normal_y;
  Lanes overlap, r_eff, m_eff, arm_i, arm_j, v_normal, v_tangent;

  Lanes overlap_rate() const { return -v_normal; }
};

/// pair_geometry for two pairs: d = r_i - r_j, dist = |d| > 0, velocities by components.
inline ContactLanes pair_geometry(Lanes dx, Lanes dy, Lanes dist, Lanes r_i, Lanes r_j, Lanes m_i,
                                  Lanes m_j, Lanes vx_i, Lanes vy_i, Lanes vx_j, Lanes vy_j,
                                  Lanes w_i, Lanes w_j, bool with_r_eff) {
  ContactLanes g;
  const Lanes inverse = 1.0 / dist;
  g.normal_x = inverse * dx;
  g.normal_y = inverse * dy;
  g.overlap = r_i + r_j - dist;
  g.r_eff = with_r_eff ? r_i * r_j / (r_i + r_j) : Lanes{};
  g.m_eff = m_i * m_j / (m_i + m_j);
  g.arm_i = r_i - 0.5 * g.overlap;
  g.arm_j = r_j - 0.5 * g.overlap;
  const Lanes dvx = vx_i - vx_j, dvy = vy_i - vy_j;
  g.v_normal = dvx * g.normal_x + dvy * g.normal_y;
  g.v_tangent = (dvx * -g.normal_y + dvy * g.normal_x) - (w_i * g.arm_i + w_j * g.arm_j);
  return g;
}

/// ContactForce of two contacts (without the normal force's magnitude).
struct ForceLanes {
  Lanes force_x, force_y; // on i; j gets the opposite
  Lanes torque_i, torque_j;
};

/// contact_force for two contacts; `history` holds their tangential springs.
template <class N, class T>
inline ForceLanes contact_force(const PairLanes& p, const ContactLanes& g, Lanes& history,
                                double dt) {
  const Lanes normal_force = N::force(p, g);
  const Lanes kn = N::stiffness(p, g);
  const Lanes ft = T::force(p, g, normal_force, kn, history, dt);
  return {normal_force * g.normal_x + ft * -g.normal_y, normal_force * g.normal_y + ft * g.normal_x,
          -g.arm_i * ft, -g.arm_j * ft};
}

} // namespace talus
