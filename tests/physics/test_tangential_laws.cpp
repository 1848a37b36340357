// Tangential laws against their definitions, and a damping rate given LAMMPS' way.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/contact_vectors.hpp"
#include "materials/timestep.hpp"
#include "physics/reference_values.hpp"
#include "support/two_body.hpp"
#include "talus/law_table.hpp"

namespace talus {
namespace {

ContactGeometry touching(double overlap, double v_tangent) {
  ContactGeometry g;
  g.normal_x = 1.0;
  g.normal_y = 0.0;
  g.overlap = overlap;
  g.r_eff = 5e-4;
  g.m_eff = 1e-5;
  g.arm_i = g.arm_j = 1e-3 - overlap / 2;
  g.v_normal = 0.0;
  g.v_tangent = v_tangent;
  return g;
}

PairParameters params() {
  Material m;
  m.young = 1e8;
  m.poisson = 0.3;
  m.normal_stiffness = 1e4;
  m.friction = 0.5;
  return mix(m, m, 1.0);
}

TEST(TangentialLaws, MindlinStiffnessIsEightGStarSqrtRXi) {
  const PairParameters p = params();
  const ContactGeometry g = touching(1e-6, 1e-3);
  double s = 0.0;
  const double dt = 1e-7; // a small step: the spring stays far below mu F_n
  const ContactForce f = contact_force<HertzViscoelastic, MindlinNoSlip>(p, g, s, dt);
  const double kt = 8.0 * p.effective_shear * std::sqrt(g.r_eff * g.overlap);
  EXPECT_DOUBLE_EQ(s, 1e-3 * dt);
  EXPECT_NEAR(dot(force_of(f), tangent_of(g)), -kt * s, 1e-12 * kt * s);
  // torques: both grains are turned the same way by a tangential force (-a F_t each)
  EXPECT_NEAR(f.torque_i, g.arm_i * kt * s, 1e-15);
  EXPECT_NEAR(f.torque_j, g.arm_j * kt * s, 1e-15);
}

TEST(TangentialLaws, CundallStrackSlipsAtMuFnAndResetsItsSpring) {
  const PairParameters p = params();
  const ContactGeometry g = touching(1e-5, 0.1);
  double s = 0.0;
  ContactForce f{};
  for (int k = 0; k < 1000; ++k)
    f = contact_force<LinearSpringDashpot, CundallStrack>(p, g, s, 1e-6);
  const double fn = p.normal_stiffness * g.overlap;
  EXPECT_NEAR(f.normal_force, fn, 1e-15);
  EXPECT_NEAR(dot(force_of(f), tangent_of(g)), -0.5 * fn, 1e-15); // sliding: F_t = -mu F_n
  const double kt = p.tangential_stiffness_ratio * p.normal_stiffness;
  EXPECT_NEAR(s, 0.5 * fn / kt, 1e-15); // the spring carries exactly the Coulomb force
}

TEST(TangentialLaws, ViscousCoulombIsCappedAndOpposesSlip) {
  PairParameters p = params();
  p.tangential_damping = 1e3;
  double s = 0.0;
  const ContactGeometry slow = touching(1e-5, -1e-3), fast = touching(1e-5, 10.0);
  const double fn = p.normal_stiffness * 1e-5;
  const auto ft = [&](const ContactGeometry& g) {
    return dot(force_of(contact_force<LinearSpringDashpot, ViscousCoulomb>(p, g, s, 1e-6)),
               tangent_of(g));
  };
  EXPECT_NEAR(ft(slow), 1e3 * 1e-5 * 1e-3, 1e-18); // viscous: gamma_t m* |v_t|, opposing
  EXPECT_NEAR(ft(fast), -0.5 * fn, 1e-15);         // capped at mu F_n
  EXPECT_EQ(s, 0.0);                               // no history
}

// A damping rate gamma_n (1/s) as LAMMPS' gran/hooke takes it gives the restitution of the
// never-attractive dashpot eta = gamma_n m*.
// Frictionless (the `none` law): a spinning disk that hits a flat floor obliquely, made of a
// material with friction and a tangential damper, still feels no tangential force and no torque.
// Analytic: the floor's normal is fixed, so the velocity along the floor and the spin are
// unchanged, and the normal velocity comes back times the linear law's restitution.
// Tolerances: the spin exactly (no torque is ever added); the velocity along the floor to 1e-15
// relative (the Gear corrector rounds the velocity once per step even when its acceleration is
// zero); the restitution to 1e-2, since at the instant the never-attractive force reaches zero
// the force has a kink that Gear's predictor does not follow (0.3% at 200 steps per collision).
TEST(TangentialLaws, FrictionlessKeepsTangentialVelocityAndSpin) {
  Material m = testing::elastic_material();
  m.restitution = 0.5;
  m.friction = 0.8;
  m.tangential_damping = 1e3;
  const double r = 1e-3, v = 0.1;
  World w;
  w.materials = {m};
  w.add_particle({.position = {0.0, 1.05 * r}, .radius = r, .velocity = {0.03, -v}});
  w.particles.angular_velocity[0] = 5.0;
  w.walls.push_back(Segment{.a = {-1.0, 0.0}, .b = {1.0, 0.0}});
  SimulationConfig c;
  c.timestep = linear_collision_time(m.normal_stiffness, 0.0, w.particles.mass[0]) / 200.0;
  c.tangential_law = law_id<Frictionless>;
  Simulation s(std::move(w), c);
  const auto rec = testing::collide(s, 100000, [](const Simulation& sim) {
    const auto& p = sim.world().particles;
    return p.radius[0] - p.position[0].y;
  });
  ASSERT_TRUE(rec.separated);
  const auto& p = s.world().particles;
  EXPECT_EQ(p.angular_velocity[0], 5.0);
  EXPECT_NEAR(p.velocity[0].x, 0.03, 1e-15 * 0.03);
  EXPECT_NEAR(p.velocity[0].y / v, 0.5, 1e-2);
}

TEST(TangentialLaws, LammpsStyleDampingRateGivesItsRestitution) {
  Material m = testing::elastic_material(1e5);
  m.normal_damping_rate = 100.0;
  World w = testing::two_grains(m, 4.5e-3, 0.1, 0.0, Shape::sphere, 0.01);
  const double m_eff = 0.5 * w.particles.mass[0];
  const double eta = 100.0 * m_eff;
  SimulationConfig c;
  c.timestep = linear_collision_time(1e5, eta, m_eff) / 200.0;
  c.tangential_law = law_id<ViscousCoulomb>;
  Simulation s(std::move(w), c);
  ASSERT_TRUE(testing::collide(s, 1'000'000).separated);
  const auto& p = s.world().particles;
  const double e = linear_restitution(1e5, eta, m_eff);
  EXPECT_NEAR((p.velocity[1].x - p.velocity[0].x) / 0.1, e, 0.005 * e);
}

// The default Cundall-Strack ratio is Mindlin's: the no-slip tangential stiffness 8 G* a over
// Hertz' normal tangent stiffness 2 E* a, 4 G* / E*, which for one material is
// 2 (1 - nu) / (2 - nu) (Mindlin 1949). Exact up to rounding: 1e-14 relative.
TEST(TangentialLaws, DefaultCundallStrackRatioIsMindlins) {
  Material a;
  a.young = 1e8;
  a.poisson = 0.3;
  const double own = 2.0 * (1.0 - 0.3) / (2.0 - 0.3);
  EXPECT_NEAR(mix(a, a, 1.0).tangential_stiffness_ratio, own, 1e-14 * own);
  Material b = a;
  b.young = 7e10;
  b.poisson = 0.2;
  const PairParameters ab = mix(a, b, 1.0);
  const double pair = 4.0 * ab.effective_shear / ab.effective_young;
  EXPECT_NEAR(ab.tangential_stiffness_ratio, pair, 1e-14 * pair);
  b.rigid = true; // against a rigid wall: the grain's own
  EXPECT_NEAR(mix(a, b, 1.0).tangential_stiffness_ratio, own, 1e-14 * own);
  b.rigid = false;
  b.tangential_stiffness_ratio = 0.5; // one given: the mean of it and the other's own
  EXPECT_NEAR(mix(a, b, 1.0).tangential_stiffness_ratio, 0.5 * (0.5 + own), 1e-15);
  // so with the Hertz law Cundall-Strack is Mindlin's no-slip spring
  const ContactGeometry g = touching(1e-6, 1e-3);
  double s_cs = 0.0, s_mindlin = 0.0;
  const double f_cs = dot(
      force_of(contact_force<HertzViscoelastic, CundallStrack>(ab, g, s_cs, 1e-7)), tangent_of(g));
  const double f_mindlin =
      dot(force_of(contact_force<HertzViscoelastic, MindlinNoSlip>(ab, g, s_mindlin, 1e-7)),
          tangent_of(g));
  EXPECT_NEAR(f_cs, f_mindlin, 1e-14 * std::abs(f_mindlin));
}

// A disk hits a wall obliquely and sticks: the contact point leaves with
// cos(pi sqrt(3 kappa)) times its tangential velocity (reference_values.hpp), for a given
// kappa = 2/7 and for the default (Mindlin's, 2 (1 - nu) / (2 - nu) at nu = 0.3).
TEST(TangentialLaws, StickingObliqueImpactTurnsTheSlipAsTheSpringSays) {
  for (const double kappa : {2.0 / 7.0, -1.0}) {
    Material m = testing::elastic_material(1e5);
    m.friction = 1e4; // never slides
    m.tangential_stiffness_ratio = kappa;
    const double r = 1e-3, v_n = 0.0025, u = 2.5e-4;
    World w;
    w.materials = {m};
    w.add_particle({.position = {0.0, 1.01 * r}, .radius = r, .velocity = {u, -v_n}});
    w.walls.push_back(Segment{.a = {-1.0, 0.0}, .b = {1.0, 0.0}});
    SimulationConfig c;
    c.timestep = linear_collision_time(m.normal_stiffness, 0.0, w.particles.mass[0]) /
                 reference::conservation_steps_per_collision;
    c.integrator = Integrator::verlet;
    c.tangential_law = law_id<CundallStrack>;
    Simulation s(std::move(w), c);
    const auto rec = testing::collide(s, 1'000'000, [](const Simulation& sim) {
      const auto& p = sim.world().particles;
      return p.radius[0] - p.position[0].y;
    });
    ASSERT_TRUE(rec.separated);
    const auto& p = s.world().particles;
    const double k = kappa > 0.0 ? kappa : 2.0 * 0.7 / 1.7;
    const double slip = p.velocity[0].x + p.angular_velocity[0] * r; // the contact point's
    EXPECT_NEAR(slip / u, std::cos(std::numbers::pi * std::sqrt(3.0 * k)),
                reference::sticking_tangential_tolerance)
        << "kappa " << k;
  }
}

} // namespace
} // namespace talus
