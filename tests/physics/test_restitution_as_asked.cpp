// materials.restitution is the restitution every pair that meets has at the impact speed: grains
// of different sizes and materials, and a grain against a wall, rigid or not, for both normal
// laws (issue 26). The Hertz law's damping is derived per contact (pair_parameters.hpp), the
// linear law's dashpot per pair of masses. Tolerance 1e-3 (absolute), the bound: each
// impact is resolved with t_c / 2000, where the start and end of the contact inside a step cost
// far less than that.
#include <gtest/gtest.h>

#include <cmath>

#include "simulation/simulation.hpp"
#include "talus/closed_forms.hpp"

namespace talus {
namespace {

constexpr double impact_v = 0.4; // m/s: the impact speed, and the config's reference speed

Material grain(double young, double restitution) {
  Material m;
  m.young = young, m.poisson = 0.3, m.restitution = restitution;
  m.normal_stiffness = young * 1e-3; // N/m, for the linear law
  m.hertz_damping = -1.0;            // derived from the restitution
  m.friction = 0.0;
  return m;
}

SimulationConfig config(NormalLaw law, double dt) {
  SimulationConfig c;
  c.timestep = dt;
  c.normal_law = law;
  c.tangential_law = law_id<Frictionless>;
  c.integrator = Integrator::gear;
  c.impact_speed = impact_v;
  return c;
}

// Runs until grain 0 has left its contact and returns the normal speed of separation over v: along
// x for two grains, y for a grain on a floor.
double rebound(World w, NormalLaw law, double dt, bool floor) {
  Simulation s(std::move(w), config(law, dt));
  const auto& p = s.world().particles;
  const auto relative = [&] { return floor ? p.velocity[0].y : p.velocity[1].x - p.velocity[0].x; };
  bool touched = false;
  for (int step = 0; step < 2'000'000; ++step) {
    s.step();
    const double gap = floor ? p.position[0].y - p.radius[0]
                             : p.position[1].x - p.position[0].x - p.radius[0] - p.radius[1];
    if (gap < 0.0) touched = true;
    if (touched && gap > 0.0) return relative() / impact_v;
  }
  ADD_FAILURE() << "no rebound";
  return 0.0;
}

// The shortest contact of the pair, for the timestep: Hertz at v, or the linear law's.
double contact_time(const Material& a, const Material& b, NormalLaw law, double m_eff,
                    double r_eff) {
  const PairParameters p = mix(a, b, impact_v);
  return with_normal_law(law,
                         [&]<class N>() { return N::collision_time(p, m_eff, r_eff, impact_v); });
}

class RestitutionAsAsked : public ::testing::TestWithParam<NormalLaw> {};

// A small grain and one three times its size, then two materials (asked: the mean, 0.5).
TEST_P(RestitutionAsAsked, TwoGrainsOfDifferentSizesAndMaterials) {
  const NormalLaw law = GetParam();
  struct Case {
    Material a, b;
    double ra, rb, asked;
  };
  for (const Case& c : {Case{grain(1e8, 0.3), grain(1e8, 0.3), 1e-3, 3e-3, 0.3},
                        Case{grain(1e8, 0.3), grain(5e8, 0.7), 2e-3, 1e-3, 0.5}}) {
    World w;
    w.materials = {c.a, c.b};
    w.add_particle({.position = {0.0, 0.0}, .radius = c.ra, .velocity = {0.5 * impact_v, 0.0}});
    w.add_particle({.position = {c.ra + c.rb + 1e-6, 0.0},
                    .radius = c.rb,
                    .material = 1,
                    .velocity = {-0.5 * impact_v, 0.0}});
    const double ma = w.particles.mass[0], mb = w.particles.mass[1];
    const double tc = contact_time(c.a, c.b, law, ma * mb / (ma + mb), c.ra * c.rb / (c.ra + c.rb));
    EXPECT_NEAR(rebound(std::move(w), law, tc / 2000.0, false), c.asked, 1e-3)
        << name_of(law) << ": radii " << c.ra << ", " << c.rb << "; asked " << c.asked;
  }
}

// A grain on a floor of another material, then on a rigid floor; e = 0.1 is below the linear
// law's floor, so only the Hertz law is asked it.
TEST_P(RestitutionAsAsked, AGrainOnAWallRigidOrNot) {
  const NormalLaw law = GetParam();
  for (const bool rigid : {false, true})
    for (const double asked : {0.1, 0.5, 0.9}) {
      if (law == law_id<LinearSpringDashpot> && asked < linear_restitution_floor) continue;
      const Material g = grain(1e8, asked);
      Material wall = grain(rigid ? 1e30 : 3e8, asked);
      wall.rigid = rigid;
      World w;
      w.materials = {g, wall};
      w.add_wall({-0.05, 0.0}, {0.05, 0.0}, 1);
      const double r = 1.5e-3;
      w.add_particle({.position = {0.0, r + 1e-6}, .radius = r, .velocity = {0.0, -impact_v}});
      const double tc = contact_time(g, wall, law, w.particles.mass[0], r);
      EXPECT_NEAR(rebound(std::move(w), law, tc / 2000.0, true), asked, 1e-3)
          << name_of(law) << (rigid ? ", rigid" : ", soft") << " wall; asked " << asked;
    }
}

INSTANTIATE_TEST_SUITE_P(BothNormalLaws, RestitutionAsAsked,
                         ::testing::Values(law_id<LinearSpringDashpot>, law_id<HertzViscoelastic>),
                         [](const auto& law) { return std::string(name_of(law.param)); });

// The dimensionless damping reproduces the restitution it was solved for, and a pair's A at the
// impact speed is the A the inverse of hertz_restitution gives (closed_forms.hpp).
TEST(HertzDamping, PerContactDampingIsTheInverseOfTheRestitution) {
  for (const double e : {0.05, 0.3, 0.8, 0.99}) {
    const double m_eff = 2e-3, rho = 4e6;
    const double A = hertz_damping_scale(e, impact_v) * std::pow(m_eff / rho, 0.4);
    EXPECT_NEAR(hertz_restitution(A, m_eff, rho, impact_v), e, 1e-9) << "e = " << e;
    EXPECT_NEAR(hertz_damping_for_restitution(e, m_eff, rho, impact_v), A, 1e-12 * A);
  }
}

} // namespace
} // namespace talus
