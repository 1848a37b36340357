// pair_style granthesis in its host (LAMMPS, or LIGGGHTS: the same file in both test programs)
// against the native engine and the closed forms: single contacts to the bit, two-disk collisions
// for both normal laws.
#include <gtest/gtest.h>

#include <cstdio>

#include "physics/reference_values.hpp"
#include "talus/closed_forms.hpp"
#include "two_disks.hpp"

namespace talus::lammps_test {
namespace {

// The force and torque LAMMPS applies to each disk are the native engine's, bit for bit: both
// evaluate the laws in src/talus on the same doubles (a pair listed as (j, i) by LAMMPS gives the
// same bits: every operation of the geometry is symmetric, or negated exactly, under the swap).
TEST(PairGranthesis, SingleContactsEqualTheNativeEngineBitForBit) {
  RandomStream rng(2026, 23);
  const double dt = 1e-6;
  for (const char* normal : {"linear", "hertz"})
    for (const char* tangential : {"coulomb", "none"})
      for (const bool newton : {true, false})
        for (int trial = 0; trial < 5; ++trial) {
          SCOPED_TRACE(words({normal, tangential, newton ? "newton on" : "newton off", "trial",
                              std::to_string(trial)}));
          const std::vector<Disk> disks = random_pair(rng);
          const Material m = grains();
          LammpsInstance l;
          set_up(l, words({normal, tangential}), m, disks, newton, dt);
          l.command("run 0");
          const Simulation s = native(normal, tangential, m, disks, dt);
          const Particles& p = s.world().particles;
          for (int k = 0; k < 2; ++k) {
            EXPECT_EQ(l.force(k + 1)[0], p.force[static_cast<std::size_t>(k)].x);
            EXPECT_EQ(l.force(k + 1)[1], p.force[static_cast<std::size_t>(k)].y);
            EXPECT_EQ(l.torque(k + 1)[2], p.torque[static_cast<std::size_t>(k)]);
          }
          EXPECT_NE(l.force(1)[0], 0.0); // they do touch
        }
}

// The linear law's restitution and duration are the never-attractive closed forms (Schwager &
// Poeschel 2007), within reference::linear_tolerance; resolving the contact with 2000 steps leaves
// the counted duration one step (5e-4 of it) from the exact one. Momentum: rounding only.
TEST(PairGranthesis, LinearCollisionMeetsTheClosedForms) {
  Material m = grains();
  m.normal_damping_rate = 4000.0; // e about 0.87
  const double mass = 2.0e-4, m_eff = 0.5 * mass;
  const double dashpot = m.normal_damping_rate * m_eff;
  const double tc = linear_collision_time(m.normal_stiffness, dashpot, m_eff);
  const Collision c = collide("linear coulomb", m, 0.005, mass, 0.1, tc / 2000.0);
  std::printf("linear: e = %.6f (closed form %.6f), t_c = %.4e s (closed form %.4e s)\n",
              c.restitution, linear_restitution(m.normal_stiffness, dashpot, m_eff), c.duration,
              tc);
  EXPECT_NEAR(c.restitution, linear_restitution(m.normal_stiffness, dashpot, m_eff),
              reference::linear_tolerance * c.restitution);
  EXPECT_NEAR(c.duration, tc, reference::linear_tolerance * tc);
  EXPECT_NEAR(c.momentum_after, c.momentum_before,
              reference::roundoff_tolerance * mass * 0.1 + 1e-20);
}

// The viscoelastic Hertz law's restitution at the impact speed (Brilliantov et al., by accurate
// integration: hertz_restitution) and, for a nearly elastic contact, the elastic duration
// (Landau & Lifshitz), within reference::hertz_tolerance.
TEST(PairGranthesis, HertzCollisionMeetsTheClosedForms) {
  Material m = grains();
  m.hertz_damping = 1.0e-5; // e about 0.85 at this speed
  const double mass = 2.0e-4, m_eff = 0.5 * mass, radius = 0.005, speed = 0.1;
  const double rho = hertz_rho(effective_young(m, m), 0.5 * radius);
  const double tc = hertz_collision_time(m_eff, rho, 2.0 * speed); // at the relative speed
  const Collision c = collide("hertz coulomb", m, radius, mass, speed, tc / 2000.0);
  std::printf("hertz: e = %.6f (closed form %.6f), t_c = %.4e s (elastic %.4e s)\n", c.restitution,
              hertz_restitution(m.hertz_damping, m_eff, rho, 2.0 * speed), c.duration, tc);
  EXPECT_NEAR(c.restitution, hertz_restitution(m.hertz_damping, m_eff, rho, 2.0 * speed),
              reference::hertz_tolerance * c.restitution);
  EXPECT_NEAR(c.duration, tc, 0.05 * tc); // the damping changes the elastic duration a little
  EXPECT_NEAR(c.momentum_after, c.momentum_before,
              reference::roundoff_tolerance * mass * speed + 1e-20);
}

// A Hertz damping left to be derived (hertz_damping -1) reaches the asked restitution at the
// pair_style's impact speed, as natively. Tolerance 1e-3 (absolute), the bound of
// RestitutionAsAsked.* for the native engine.
TEST(PairGranthesis, DerivedHertzDampingGivesTheRestitutionAtTheImpactSpeed) {
  Material m = grains();
  m.hertz_damping = -1.0, m.restitution = 0.6;
  const double mass = 2.0e-4, m_eff = 0.5 * mass, radius = 0.005, speed = 0.1;
  const double rho = hertz_rho(effective_young(m, m), 0.5 * radius);
  const double tc = hertz_collision_time(m_eff, rho, 2.0 * speed);
  const Collision c =
      collide("hertz coulomb impact_speed 0.2", m, radius, mass, speed, tc / 2000.0);
  EXPECT_NEAR(c.restitution, 0.6, 1e-3);
}

// An unknown coefficient stops the host with the key and the allowed ones, in LIGGGHTS as in
// LAMMPS (test_pair_granthesis.cpp has the rest of LAMMPS' bad input).
TEST(PairGranthesis, UnknownCoefficientNamesTheAllowedKeys) {
  expect_deck_error({"dimension 2", "units si", "atom_style sphere", "boundary f f p",
                     ghost_velocities, "region box block -1 1 -1 1 -0.01 0.01", "create_box 1 box",
                     "create_atoms 1 single 0 0 0", "set atom * diameter 0.01",
                     "set atom * mass 2e-4", "pair_style granthesis linear coulomb",
                     "pair_coeff 1 1 stiffness 1e5"},
                    "unknown key 'stiffness'; allowed: young, poisson");
}

} // namespace
} // namespace talus::lammps_test
