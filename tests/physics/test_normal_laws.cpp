// Single-contact closed forms: linear spring-dashpot and Hertz, elastic and viscoelastic.
#include <gtest/gtest.h>

#include <cmath>

#include "materials/timestep.hpp"
#include "physics/reference_values.hpp"
#include "support/two_body.hpp"

namespace talus {
namespace {

using testing::collide;
using testing::two_grains;

constexpr double law_r = 1.0e-3;

struct Outcome {
  double restitution;
  double contact_time;
  double max_overlap;
  double max_force;
};

Outcome head_on(const Material& m, NormalLaw law, Integrator integrator, double v, double dt,
                Shape shape = Shape::disk) {
  World w = two_grains(m, law_r, v, 0.0, shape, 0.01);
  SimulationConfig c;
  c.timestep = dt;
  c.normal_law = law;
  c.tangential_law = law_id<ViscousCoulomb>;
  c.integrator = integrator;
  c.impact_speed = v; // where a derived Hertz damping reaches the restitution
  Simulation s(std::move(w), c);
  const auto rec = collide(s, 10'000'000);
  EXPECT_TRUE(rec.separated);
  const auto& p = s.world().particles;
  return {(p.velocity[1].x - p.velocity[0].x) / v, rec.contact_time, rec.max_overlap,
          rec.max_force};
}

class LinearLaw : public ::testing::TestWithParam<Integrator> {};

// The textbook form e = exp(-pi b/omega), t_c = pi/omega, at weak damping where the
// never-attractive correction (0.22% at e = 0.9) is inside the tolerance.
TEST_P(LinearLaw, MatchesTextbookRestitutionAndDurationAtWeakDamping) {
  Material m = testing::elastic_material(1.0e4);
  m.restitution = 0.9;
  const double mass = shape_mass(Shape::disk, law_r, m.density), m_eff = 0.5 * mass;
  const double eta = mix(m, m, 1.0).normal_dashpot(m_eff);
  const double tc = linear_collision_time_textbook(m.normal_stiffness, eta, m_eff);
  const Outcome o = head_on(m, law_id<LinearSpringDashpot>, GetParam(), 0.02,
                            tc / reference::linear_steps_per_collision);
  const double e = linear_restitution_textbook(m.normal_stiffness, eta, m_eff);
  EXPECT_NEAR(o.restitution, e, e * reference::linear_tolerance);
  EXPECT_NEAR(o.contact_time, tc, tc * reference::linear_tolerance);
}

// The exact values of the never-attractive law over the whole range of restitution. Strong
// damping makes the grains part while the force is still steep, mid-step: at t_c/50 that costs
// 1.6% at e = 0.5, so this test resolves the contact with t_c/200.
TEST_P(LinearLaw, MatchesExactRestitutionAndDurationAtAnyDamping) {
  for (const double target : {0.95, 0.7, 0.5, 0.3}) {
    Material m = testing::elastic_material(1.0e4);
    m.restitution = target;
    const double mass = shape_mass(Shape::disk, law_r, m.density), m_eff = 0.5 * mass;
    const double eta = mix(m, m, 1.0).normal_dashpot(m_eff);
    EXPECT_NEAR(linear_restitution(m.normal_stiffness, eta, m_eff), target, 1e-12);
    const double tc = linear_collision_time(m.normal_stiffness, eta, m_eff);
    const Outcome o = head_on(m, law_id<LinearSpringDashpot>, GetParam(), 0.02, tc / 200.0);
    EXPECT_NEAR(o.restitution, target, target * reference::linear_tolerance) << "e = " << target;
    EXPECT_NEAR(o.contact_time, tc, tc * reference::linear_tolerance) << "e = " << target;
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, LinearLaw,
                         ::testing::Values(Integrator::gear, Integrator::verlet),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

Material hertz_material(double damping_A = 0.0) {
  Material m = testing::elastic_material();
  m.young = 1.0e8; // Pa: a soft grain keeps the contact long enough to resolve cheaply
  m.poisson = 0.3;
  m.hertz_damping = damping_A;
  return m;
}

TEST(HertzLaw, ElasticCollisionMatchesClosedForms) {
  const Material m = hertz_material();
  for (const double v : {0.01, 0.1, 1.0}) {
    const double mass = shape_mass(Shape::sphere, law_r, m.density), m_eff = 0.5 * mass;
    const double e_star = effective_young(m, m), r_eff = 0.5 * law_r;
    const double rho = hertz_rho(e_star, r_eff);
    const double tc_ref = reference::hertz_time_constant *
                          std::pow(m_eff * m_eff / (r_eff * e_star * e_star * v), 0.2);
    const double xi_ref = std::pow(5.0 * m_eff * v * v / (4.0 * rho), 0.4);
    const double f_ref = rho * std::pow(xi_ref, 1.5);
    const Outcome o =
        head_on(m, law_id<HertzViscoelastic>, Integrator::gear, v, tc_ref / 200.0, Shape::sphere);
    EXPECT_NEAR(o.contact_time, tc_ref, tc_ref * reference::hertz_tolerance) << "v = " << v;
    EXPECT_NEAR(o.max_overlap, xi_ref, xi_ref * reference::hertz_tolerance) << "v = " << v;
    EXPECT_NEAR(o.max_force, f_ref, f_ref * reference::hertz_tolerance) << "v = " << v;
    EXPECT_NEAR(o.restitution, 1.0, 1e-5); // the contact-kink error, as for the linear law
    // the library's own helpers agree with the references
    EXPECT_NEAR(hertz_collision_time(m_eff, rho, v), tc_ref, tc_ref * 1e-3);
    EXPECT_NEAR(hertz_max_overlap(m_eff, rho, v), xi_ref, xi_ref * 1e-12);
  }
}

// Ramirez et al. 1999: e(v) = 1 - C1 (3A/2) alpha^(2/5) v^(1/5) + C2 ((3A/2) alpha^(2/5) v^(1/5))^2
TEST(HertzLaw, ViscoelasticRestitutionFollowsRamirez) {
  const double mass = shape_mass(Shape::sphere, law_r, 2650.0), m_eff = 0.5 * mass;
  Material m = hertz_material();
  const double rho = hertz_rho(effective_young(m, m), 0.5 * law_r);
  const double alpha = rho / m_eff;
  // A such that the first-order term is 0.1 at v = 1 m/s (e about 0.89 there)
  m.hertz_damping = 0.1 / reference::ramirez_c1 / 1.5 / std::pow(alpha, 0.4);
  for (const double v : {0.01, 0.03, 0.1, 0.3, 1.0}) {
    const double x = 1.5 * m.hertz_damping * std::pow(alpha, 0.4) * std::pow(v, 0.2);
    const double e_ref = 1.0 - reference::ramirez_c1 * x + reference::ramirez_c2 * x * x;
    const double tc = hertz_collision_time(m_eff, rho, v);
    const Outcome o =
        head_on(m, law_id<HertzViscoelastic>, Integrator::gear, v, tc / 200.0, Shape::sphere);
    EXPECT_NEAR(o.restitution, e_ref, e_ref * reference::ramirez_tolerance) << "v = " << v;
    // and the helper that integrates the single contact agrees with the simulation
    EXPECT_NEAR(hertz_restitution(m.hertz_damping, m_eff, rho, v), o.restitution, 2e-3);
  }
}

// The Hertz law reaches any restitution in (0, 1], below the linear law's floor exp(-2) too: a
// material with e = 0.1 or 0.05 mixes (the linear dashpot is not derived for it) and a head-on
// collision at the impact speed rebounds with it. Tolerance 1e-3 (absolute): strong damping
// makes the grains part mid-step, resolved here with t_c / 1000.
TEST(HertzLaw, AnyRestitutionIsReachedBelowTheLinearFloor) {
  const double v = 0.5, mass = shape_mass(Shape::sphere, law_r, 2650.0);
  for (const double e : {0.1, 0.05}) {
    Material m = hertz_material();
    m.restitution = e, m.hertz_damping = -1.0;
    EXPECT_EQ(HertzViscoelastic::material_error(m), "");
    EXPECT_NE(LinearSpringDashpot::material_error(m), "") << "the linear law cannot reach it";
    const PairParameters p = mix(m, m, v); // no longer refused with the linear law's message
    const double tc = HertzViscoelastic::collision_time(p, 0.5 * mass, 0.5 * law_r, v);
    const Outcome o =
        head_on(m, law_id<HertzViscoelastic>, Integrator::gear, v, tc / 1000.0, Shape::sphere);
    EXPECT_NEAR(o.restitution, e, 1e-3) << "e = " << e;
  }
}

TEST(HertzLaw, DampingForRestitutionInvertsRestitution) {
  const double m_eff = 1.0e-5, rho = hertz_rho(5.0e7, 5.0e-4);
  for (const double e : {0.95, 0.8, 0.5}) {
    const double a = hertz_damping_for_restitution(e, m_eff, rho, 0.5);
    EXPECT_NEAR(hertz_restitution(a, m_eff, rho, 0.5), e, 1e-9);
  }
}

} // namespace
} // namespace talus
