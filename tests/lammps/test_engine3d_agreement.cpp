// The native 3D engine (native/engine3d) with LAMMPS' velocity convention (verlet_velocity =
// half_step, as under fix nve/sphere) against LAMMPS with pair_style granthesis in 3D: two
// spheres through a whole oblique collision with spins about every axis, for every law pair with
// and without a spring, and spheres colliding across the sides of a box periodic along every
// axis, agree to rounding: the two engines share the contact laws, not the integrator, the
// neighbour lists, the periodic images or the order of the force sums.
#include <gtest/gtest.h>

#include <cmath>

#include "native3d.hpp"

namespace talus::lammps_test {
namespace {

Difference after(const std::string& normal, const std::string& tangential,
                 const std::vector<Sphere>& spheres, double dt, int steps,
                 const Domain3& domain = {}, const std::string& boundary = "f f f",
                 const std::string& box = "-0.1 0.1 -0.1 0.1 -0.1 0.1") {
  const Material m = spheres_material();
  LammpsInstance l;
  set_up_3d(l, normal + " " + tangential, m, spheres, dt, boundary, box);
  l.commands({"fix move all nve/sphere", "run " + std::to_string(steps)});
  Simulation3 s = run_as_lammps(native_scene(m, spheres, domain), normal, tangential, dt);
  s.run(static_cast<std::uint64_t>(steps));
  return between(l, s);
}

// Rounding: the engines order a few operations differently (the kick's 1/m, the contacts' sums),
// a few ulp a step over 3000 steps: below 1e-12 of the speeds and spins, 1e-15 m of positions.
TEST(Engine3DAgreement, AnObliqueCollisionAgreesWithLammpsToRounding) {
  for (const std::string normal : {"linear", "hertz"})
    for (const std::string tangential : {"coulomb", "cundall_strack", "mindlin"}) {
      SCOPED_TRACE(normal + " " + tangential);
      const Difference d = after(normal, tangential, oblique_pair(), 1e-7, 3000);
      std::printf("%s %s: %.2e m, %.2e m/s, %.2e rad/s\n", normal.c_str(), tangential.c_str(),
                  d.position, d.velocity, d.spin);
      EXPECT_LT(d.position, 1e-15);
      EXPECT_LT(d.velocity, 1e-12 * 0.1);
      EXPECT_LT(d.spin, 1e-12 * 30.0);
    }
  // and they did collide: the first sphere was turned round
  Simulation3 s =
      run_as_lammps(native_scene(spheres_material(), oblique_pair()), "hertz", "mindlin", 1e-7);
  s.run(3000);
  EXPECT_LT(s.scene().spheres.velocity[0].x, 0.0);
  EXPECT_GT(norm(s.scene().spheres.angular_velocity[0] - oblique_pair()[0].spin), 1.0);
}

// Twelve spheres thrown at each other across the sides of a 3 cm box periodic along x, y and z:
// the images and the springs carried across sides, against LAMMPS' ghosts. Rounding as above,
// over fewer steps: every collision after the first amplifies the engines' rounding.
TEST(Engine3DAgreement, CollisionsAcrossPeriodicSidesAgreeWithLammpsToRounding) {
  const std::vector<Sphere> spheres = periodic_cloud();
  const double side = cloud_side;
  const Domain3 box{
      .lo = {0.0, 0.0, 0.0}, .hi = {side, side, side}, .periodic = {true, true, true}};
  const std::string lammps_box = words({"0", exact(side), "0", exact(side), "0", exact(side)});
  Simulation3 alone =
      run_as_lammps(native_scene(spheres_material(), spheres, box), "hertz", "mindlin", 1e-6);
  std::size_t touching = 0;
  for (int k = 0; k < 20000; ++k) {
    alone.step();
    touching += alone.contact_count();
  }
  ASSERT_GT(touching, 200u) << "the spheres hardly met";
  const Difference d = after("hertz", "mindlin", spheres, 1e-6, 20000, box, "p p p", lammps_box);
  std::printf("periodic: %.2e m, %.2e m/s, %.2e rad/s\n", d.position, d.velocity, d.spin);
  EXPECT_LT(d.position, 1e-13);
  EXPECT_LT(d.velocity, 1e-11);
  EXPECT_LT(d.spin, 1e-11 * 50.0);
}

} // namespace
} // namespace talus::lammps_test
