#pragma once
// The pair parameters the lane tests (tests/unit/test_contact_lanes.cpp, its 3D twin in
// tests/engine3d) draw their contacts' laws from.
#include <vector>

#include "talus/pair_parameters.hpp"

namespace talus::testing {

/// Three parameter sets: a damping rate (LAMMPS' way), a damping from the restitution (square
/// root of m_eff), and a mixed pair; each with its own Hertz and tangential damping.
inline std::vector<PairParameters> lane_parameter_sets() {
  Material a, b, c;
  a.normal_stiffness = 1e5, a.normal_damping_rate = 100.0, a.tangential_damping = 50.0;
  a.hertz_damping = 1e-4;
  b.normal_stiffness = 3e4, b.restitution = 0.5, b.friction = 0.3, b.tangential_damping = 1e3;
  b.hertz_damping = 2e-5;
  c.young = 5e7, c.poisson = 0.25, c.hertz_damping = 1e-5, c.tangential_damping = 20.0;
  c.normal_stiffness = 2e5, c.friction = 0.8, c.restitution = 0.7;
  return {mix(a, a, 1.0), mix(b, b, 1.0), mix(b, c, 1.0)};
}

} // namespace talus::testing
