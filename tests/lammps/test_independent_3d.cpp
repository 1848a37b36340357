// The native 3D engine against LAMMPS' own gran/hooke/history and pair_style granular,
// implementations written apart from src/talus (pair_style granthesis shares the native code;
// these do not). gran/hooke/history is the linear law with Cundall-Strack springs; its
// conventions pinned, as in 2D (docs/validation.md):
// gran/hooke/history takes the lever arms at the radius (native `lever_arm = radius`), its
// dampers as rates times m_eff (native `normal_damping_rate`, `tangential_damping`), cuts the
// normal force at zero with `limit_damping` (the native never-attractive dashpot), and the
// velocity under fix nve/sphere is the half step's. Where the two differ: gran/hooke/history
// caps spring and tangential dashpot together, the native rule holds the spring alone in the
// cone, so the cases have no tangential dashpot; and it keeps its spring in the tangent plane by
// projecting it, the native rule turns it (projected and rescaled to its length), which differ
// by O(angle^2) for each step's turn of the contact.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "native3d.hpp"

namespace talus::lammps_test {
namespace {

constexpr double kn = 1e4, kt_over_kn = 0.4, gamma_n = 200.0;

Material hooke_material(double friction) {
  Material m = spheres_material();
  m.normal_stiffness = kn;
  m.tangential_stiffness_ratio = kt_over_kn;
  m.normal_damping_rate = gamma_n;
  m.tangential_damping = 0.0;
  m.friction = friction;
  return m;
}

// LAMMPS with gran/hooke/history of these constants and `friction` (dampflag 0: no tangential
// dashpot), and the native engine with the conventions above, both run `steps`.
Difference after(const std::vector<Sphere>& spheres, double dt, int steps, double friction,
                 const Domain3& domain = {}, const std::string& boundary = "f f f",
                 const std::string& box = "-0.1 0.1 -0.1 0.1 -0.1 0.1",
                 double lammps_friction = -1.0) {
  LammpsInstance l;
  spheres_in_box(l, spheres, boundary, box);
  l.commands(
      {words({"pair_style gran/hooke/history", exact(kn), exact(kt_over_kn * kn), exact(gamma_n),
              "0", exact(lammps_friction >= 0.0 ? lammps_friction : friction), "0",
              "limit_damping"}),
       "pair_coeff * *", "neighbor 0.001 bin", words({"timestep", exact(dt)}),
       "fix move all nve/sphere", "run " + std::to_string(steps)});
  Simulation3 s(native_scene(hooke_material(friction), spheres, domain),
                {.timestep = dt,
                 .normal_law = parse_normal_law("linear"),
                 .tangential_law = parse_tangential_law("cundall_strack"),
                 .verlet_velocity = VerletVelocity::half_step,
                 .lever_arm = LeverArm::radius});
  s.run(static_cast<std::uint64_t>(steps));
  return between(l, s);
}

// The oblique collision of spheres spinning about tilted axes (native3d.hpp): it slides, sticks
// and ends within 3000 steps of 1e-7 s. The two rules of the spring part by O(dt^2) a step,
// which the collision does not amplify: 3e-13 m (6e-11 radii) holds that with two orders of
// magnitude of room, and a friction changed in its fourth digit must exceed it.
TEST(Independent3D, AnObliqueCollisionAgreesWithGranHookeHistory) {
  const Difference d = after(oblique_pair(), 1e-7, 3000, 0.4);
  std::printf("oblique: %.2e m, %.2e m/s, %.2e rad/s\n", d.position, d.velocity, d.spin);
  EXPECT_LT(d.position, 3e-13);
  EXPECT_LT(d.velocity, 1e-9);
  EXPECT_LT(d.spin, 1e-9 * 30.0);
  const Difference wrong =
      after(oblique_pair(), 1e-7, 3000, 0.4, {}, "f f f", "-0.1 0.1 -0.1 0.1 -0.1 0.1", 0.4001);
  std::printf("friction 0.4001: %.2e m, %.2e m/s, %.2e rad/s\n", wrong.position, wrong.velocity,
              wrong.spin);
  EXPECT_GT(wrong.position, 3e-13);
}

// Twelve spheres thrown at each other across the sides of a box periodic along every axis
// (native3d.hpp) for 20000 steps of 1e-6 s: each collision amplifies what the ones before left,
// to well below 3e-8 m (1e-5 radii), which a friction changed in its fourth digit exceeds.
TEST(Independent3D, CollisionsAcrossPeriodicSidesAgreeWithGranHookeHistory) {
  const double side = cloud_side;
  const Domain3 box{
      .lo = {0.0, 0.0, 0.0}, .hi = {side, side, side}, .periodic = {true, true, true}};
  const std::string lammps_box = words({"0", exact(side), "0", exact(side), "0", exact(side)});
  const Difference d = after(periodic_cloud(), 1e-6, 20000, 0.4, box, "p p p", lammps_box);
  std::printf("periodic: %.2e m, %.2e m/s, %.2e rad/s\n", d.position, d.velocity, d.spin);
  const Difference wrong =
      after(periodic_cloud(), 1e-6, 20000, 0.4, box, "p p p", lammps_box, 0.4001);
  std::printf("friction 0.4001: %.2e m, %.2e m/s, %.2e rad/s\n", wrong.position, wrong.velocity,
              wrong.spin);
  EXPECT_LT(d.position, 3e-8);
  EXPECT_GT(wrong.position, 3e-8);
}

// pair_style granular's hertz/material with damping viscoelastic and tangential
// mindlin_rescale/force, against the native Hertz law with Mindlin's springs. The conventions
// pinned, as in 2D (docs/validation.md, validation/independent.py): the native viscoelastic
// force 3/2 A rho sqrt(xi) dxi/dt is granular's eta_n0 a m_eff v_n with eta_n0 = 2 A E* / m_eff
// (one pair here, so one m_eff); no tangential dashpot (granular caps it with the spring); the
// spins' velocity at the radii and the torques at R - xi/2 (native `lever_arm = granular`).
// The springs' loading rules differ by O(dt^2) a step (the native rule rescales the spring by
// the stiffness of the overlap a step before, estimated from its rate; granular keeps the
// force): 1e-12 m (2e-10 radii) holds that, and a friction changed in its fourth digit must
// exceed it.
Difference granular_after(double friction, double lammps_friction) {
  const double a = 1e-5; // s, the viscoelastic constant A
  const std::vector<Sphere> spheres = oblique_pair();
  Material m = spheres_material();
  m.hertz_damping = a;
  m.tangential_damping = 0.0;
  m.friction = friction;
  const double e_star = m.young / (2.0 * (1.0 - m.poisson * m.poisson));
  const double m_eff = spheres[0].mass * spheres[1].mass / (spheres[0].mass + spheres[1].mass);
  const double dt = 1e-7;
  const int steps = 3000;
  LammpsInstance l;
  spheres_in_box(l, spheres, "f f f", "-0.1 0.1 -0.1 0.1 -0.1 0.1");
  l.commands(
      {"pair_style granular",
       words({"pair_coeff * * hertz/material", exact(m.young), exact(2.0 * a * e_star / m_eff),
              exact(m.poisson), "tangential mindlin_rescale/force NULL 0.0", exact(lammps_friction),
              "damping viscoelastic limit_damping"}),
       "neighbor 0.001 bin", words({"timestep", exact(dt)}), "fix move all nve/sphere",
       "run " + std::to_string(steps)});
  Simulation3 s(native_scene(m, spheres), {.timestep = dt,
                                           .normal_law = parse_normal_law("hertz"),
                                           .tangential_law = parse_tangential_law("mindlin"),
                                           .verlet_velocity = VerletVelocity::half_step,
                                           .lever_arm = LeverArm::granular});
  s.run(static_cast<std::uint64_t>(steps));
  return between(l, s);
}

TEST(Independent3D, AnObliqueCollisionAgreesWithGranularHertzMindlin) {
  const Difference d = granular_after(0.4, 0.4);
  std::printf("granular: %.2e m, %.2e m/s, %.2e rad/s\n", d.position, d.velocity, d.spin);
  const Difference wrong = granular_after(0.4, 0.4001);
  std::printf("friction 0.4001: %.2e m, %.2e m/s, %.2e rad/s\n", wrong.position, wrong.velocity,
              wrong.spin);
  EXPECT_LT(d.position, 1e-12);
  EXPECT_GT(wrong.position, 1e-12);
}

} // namespace
} // namespace talus::lammps_test
