// The linear law's damping conventions (simulation.linear_damping, talus/pair_parameters.hpp):
// a head-on impact of two disks gives, for each, the restitution and the peak overlap of its
// closed form (reference_values.hpp), so that a user can reproduce another code's linear cases.
#include <gtest/gtest.h>

#include <cmath>
#include <exception>
#include <string>

#include "physics/reference_values.hpp"
#include "scenario/file/load.hpp"
#include "support/two_body.hpp"
#include "talus/closed_forms.hpp"

namespace talus {
namespace {

namespace ref = reference;

struct HeadOnImpact {
  double restitution = 0.0;
  double peak_overlap = 0.0; ///< m
  double m_eff = 0.0;        ///< kg
};

const double damping_stiffness = 1.0e4, damping_radius = 0.005, damping_speed = 0.5;

// Two equal disks head-on at `speed` with restitution e under convention d.
HeadOnImpact impact(double e, LinearDamping d) {
  Material m = testing::elastic_material(damping_stiffness);
  m.restitution = e;
  World w = testing::two_grains(m, damping_radius, damping_speed);
  const double m_eff = 0.5 * w.particles.mass[0];
  SimulationConfig c;
  c.normal_law = law_id<LinearSpringDashpot>;
  c.tangential_law = law_id<Frictionless>;
  c.integrator = Integrator::gear;
  c.linear_damping = d;
  c.timestep = std::numbers::pi * std::sqrt(m_eff / damping_stiffness) / ref::linear_damping_steps;
  Simulation s(std::move(w), c);
  const testing::CollisionRecord r = testing::collide(s, 1'000'000);
  EXPECT_TRUE(r.separated);
  const auto& v = s.world().particles.velocity;
  return {(v[1].x - v[0].x) / damping_speed, r.max_overlap, m_eff};
}

// The peak overlap of an impact at `speed` on a linear oscillator of reduced mass m_eff with
// damping ratio zeta: (v / omega_0) exp(-zeta / sqrt(1 - zeta^2) atan(sqrt(1 - zeta^2) / zeta)).
double peak(double zeta, double m_eff) {
  const double root = std::sqrt(1.0 - zeta * zeta);
  return damping_speed * std::sqrt(m_eff / damping_stiffness) *
         std::exp(-zeta / root * std::atan(root / zeta));
}

TEST(LinearDamping, EachConventionGivesItsRestitutionAndPeakOverlap) {
  for (const double e : {0.3, 0.5, 0.8}) {
    SCOPED_TRACE("e = " + std::to_string(e));
    const double never = linear_damping_ratio(e), classic = classic_damping_ratio(e);
    const HeadOnImpact a = impact(e, LinearDamping::never_attractive);
    const HeadOnImpact b = impact(e, LinearDamping::classic);
    const HeadOnImpact c = impact(e, LinearDamping::classic_cut);
    const double m_eff = a.m_eff;
    const double eta_classic = 2.0 * classic * std::sqrt(damping_stiffness * m_eff);
    const double e_cut = linear_restitution(damping_stiffness, eta_classic, m_eff);
    std::printf("e = %.2f: never_attractive %.5f (peak %.4e m), classic %.5f (%.4e m), "
                "classic_cut %.5f (%.4e m)\n",
                e, a.restitution, a.peak_overlap, b.restitution, b.peak_overlap, c.restitution,
                c.peak_overlap);
    const double tol = ref::linear_damping_tolerance;
    EXPECT_NEAR(a.restitution, e, tol * e);
    EXPECT_NEAR(b.restitution, e, tol * e);
    EXPECT_NEAR(c.restitution, e_cut, tol * e_cut);
    EXPECT_GT(c.restitution - e, 4.0 * tol * e); // the cut gives back more than asked
    EXPECT_NEAR(a.peak_overlap, peak(never, m_eff), tol * a.peak_overlap);
    EXPECT_NEAR(b.peak_overlap, peak(classic, m_eff), tol * b.peak_overlap);
    EXPECT_NEAR(c.peak_overlap, peak(classic, m_eff), tol * c.peak_overlap);
  }
}

TEST(LinearDamping, OnlyTheClassicConventionReachesARestitutionBelowTheFloor) {
  Material m = testing::elastic_material(damping_stiffness);
  m.restitution = 0.1;
  EXPECT_NE(LinearSpringDashpot::material_error(m, LinearDamping::never_attractive), "");
  EXPECT_EQ(LinearSpringDashpot::material_error(m, LinearDamping::classic), "");
  EXPECT_NEAR(impact(0.1, LinearDamping::classic).restitution, 0.1,
              ref::linear_damping_tolerance * 0.1);
}

// The key names its choices, and is refused where it does not apply.
TEST(LinearDamping, TheScenarioKeyIsCheckedAndRefusedWithTheHertzLaw) {
  const auto error_of = [](const std::string& simulation) {
    try {
      load_scenario("[simulation]\n" + simulation, "damping.toml", {});
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(load_scenario("[simulation]\nlinear_damping = \"classic_cut\"", "d.toml", {})
                .simulation.linear_damping,
            LinearDamping::classic_cut);
  EXPECT_NE(error_of("linear_damping = \"pulling\"").find("never_attractive, classic, classic_cut"),
            std::string::npos);
  const std::string hertz = error_of("normal_law = \"hertz\"\nlinear_damping = \"classic\"");
  EXPECT_NE(hertz.find("linear_damping"), std::string::npos) << hertz;
  EXPECT_NE(hertz.find("linear normal law only"), std::string::npos) << hertz;
}

} // namespace
} // namespace talus
