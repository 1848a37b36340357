// The lever-arm conventions (talus/contact_geometry.hpp, LeverArm): the contact point mid-overlap,
// R - xi/2, the default, whose arms add up to the distance of the centres, so that a pair's
// torques conserve the angular momentum exactly; or the radius, R, LAMMPS' granular styles'
// convention (validation/crosscheck.py compares it with gran/hooke), which conserves it only to
// O(xi F_t) per contact.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analysis/observables.hpp"
#include "simulation/simulation.hpp"
#include "support/two_body.hpp"

namespace talus {
namespace {

TEST(LeverArm, TheArmsReachTheContactPointOrTheRadius) {
  const double ri = 0.005, rj = 0.004, dist = 0.0089; // overlap 1e-4 m
  const auto geometry = [&](LeverArm a) {
    return pair_geometry(dist, 0.0, dist, ri, rj, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, true,
                         lever_shares(a));
  };
  const ContactGeometry point = geometry(LeverArm::contact_point);
  EXPECT_DOUBLE_EQ(point.arm_i, ri - 0.5e-4);
  EXPECT_DOUBLE_EQ(point.arm_i + point.arm_j, dist);
  const ContactGeometry radius = geometry(LeverArm::radius);
  EXPECT_EQ(radius.arm_i, ri);
  EXPECT_EQ(radius.arm_j, rj);
  // granular: the torques' arms at the contact point, the spins' velocity at the radii (i
  // spinning at 10 rad/s, j at -4 rad/s: v_t = -(w_i R_i + w_j R_j) exactly)
  const ContactGeometry granular =
      pair_geometry(dist, 0.0, dist, ri, rj, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 10.0, -4.0, true,
                    lever_shares(LeverArm::granular));
  EXPECT_EQ(granular.arm_i, point.arm_i);
  EXPECT_EQ(granular.arm_j, point.arm_j);
  EXPECT_EQ(granular.v_tangent, -(10.0 * ri + -4.0 * rj));
  for (const LeverArm a : {LeverArm::contact_point, LeverArm::radius, LeverArm::granular})
    EXPECT_EQ(parse_lever_arm(to_string(a)), a);
  EXPECT_THROW(parse_lever_arm("centre"), InvalidArgument);
}

// A sliding oblique impact of two disks with friction: with the torques' arms at the contact point
// (contact_point, granular) the angular momentum stays to rounding (bound 1e-11 of m v R; a few
// ulp a step over 4000 steps), with the radii it does not (the pair's torques exceed the moment
// of its forces by xi F_t, far above the bound 1e-5; docs/model.md).
TEST(LeverArm, OnlyTheContactPointConservesTheAngularMomentum) {
  Material m = testing::elastic_material(2.0e5);
  m.friction = 0.4;
  m.tangential_damping = 300.0;
  for (const LeverArm arm : {LeverArm::contact_point, LeverArm::radius, LeverArm::granular}) {
    World w = testing::two_grains(m, 0.005, 1.0, 0.004);
    SimulationConfig c;
    c.timestep = 2.0e-6;
    c.integrator = Integrator::verlet;
    c.tangential_law = law_id<ViscousCoulomb>;
    c.lever_arm = arm;
    Simulation s(std::move(w), c);
    const double l0 = angular_momentum(s);
    const Particles& p = s.world().particles;
    const double scale = p.mass[0] * 1.0 * 0.005; // m v R
    double drift = 0.0;
    for (int k = 0; k < 4000; ++k) {
      s.step();
      drift = std::max(drift, std::abs(angular_momentum(s) - l0) / scale);
    }
    ASSERT_NE(p.angular_velocity[0], 0.0); // friction acted
    if (arm == LeverArm::radius)
      EXPECT_GT(drift, 1e-5);
    else
      EXPECT_LT(drift, 1e-11);
    std::printf("lever arm %s: angular momentum drift %.3g of m v R\n", to_string(arm), drift);
  }
}

} // namespace
} // namespace talus
