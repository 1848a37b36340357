// Thesis chapter 3: head-on and oblique two-disk collisions conserve what they must.
#include <gtest/gtest.h>

#include <cmath>

#include "materials/timestep.hpp"
#include "physics/reference_values.hpp"
#include "support/two_body.hpp"

namespace talus {
namespace {

using testing::collide;
using testing::elastic_material;
using testing::two_grains;

constexpr double collision_r = 1.0e-3; // m

SimulationConfig
config_for(const World& w, Integrator integrator, TangentialLaw t,
           double steps_per_collision = reference::conservation_steps_per_collision) {
  SimulationConfig c;
  const double m_eff = 0.5 * w.particles.mass[0];
  c.timestep =
      linear_collision_time(w.materials[0].normal_stiffness, 0.0, m_eff) / steps_per_collision;
  c.integrator = integrator;
  c.tangential_law = t;
  return c;
}

class ElasticCollision : public ::testing::TestWithParam<Integrator> {};

TEST_P(ElasticCollision, HeadOnConservesEnergyAndReversesVelocities) {
  const double v = reference::thesis_disk_speed;
  World w = two_grains(elastic_material(), collision_r, 2.0 * v);
  const SimulationConfig c = config_for(w, GetParam(), law_id<ViscousCoulomb>);
  Simulation s(std::move(w), c);
  const double e0 = energies(s).total();
  double worst = 0.0;
  const auto rec = collide(s, 100000, testing::overlap01, [&](const Simulation& sim) {
    worst = std::max(worst, std::abs(energies(sim).total() - e0) / e0);
  });
  ASSERT_TRUE(rec.separated);
  const auto& p = s.world().particles;
  EXPECT_NEAR(p.velocity[0].x, -v, v * reference::elastic_energy_tolerance);
  EXPECT_NEAR(p.velocity[1].x, v, v * reference::elastic_energy_tolerance);
  EXPECT_EQ(p.velocity[0].y, 0.0);
  EXPECT_LT(std::abs(energies(s).total() - e0) / e0, reference::elastic_energy_tolerance);
  if (GetParam() == Integrator::gear) {
    EXPECT_LT(worst, reference::elastic_energy_tolerance);
  }
}

TEST_P(ElasticCollision, ObliqueConservesEnergy) {
  const double v = reference::thesis_disk_speed;
  World w = two_grains(elastic_material(), collision_r, 2.0 * v, /*b=*/1.2 * collision_r);
  const SimulationConfig c = config_for(w, GetParam(), law_id<ViscousCoulomb>);
  Simulation s(std::move(w), c);
  const double e0 = energies(s).total();
  const auto rec = collide(s, 100000);
  ASSERT_TRUE(rec.separated);
  const auto& p = s.world().particles;
  EXPECT_GT(std::abs(p.velocity[0].y), 0.1 * v); // deflected, as in the thesis' fig. 3.2
  EXPECT_LT(std::abs(energies(s).total() - e0) / e0, reference::elastic_energy_tolerance);
}

INSTANTIATE_TEST_SUITE_P(Integrators, ElasticCollision,
                         ::testing::Values(Integrator::gear, Integrator::verlet),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

struct LossyCase {
  Integrator integrator;
  TangentialLaw law;
};

class DissipativeFrictionalCollision : public ::testing::TestWithParam<LossyCase> {};

TEST_P(DissipativeFrictionalCollision, ConservesLinearAndAngularMomentum) {
  const double v = reference::thesis_disk_speed;
  Material m = elastic_material();
  m.restitution = 0.3; // the thesis' gamma = 1 case (sec. 3.2.2)
  m.friction = 0.5;
  m.tangential_damping = 500.0;
  World w = two_grains(m, collision_r, 2.0 * v, /*b=*/1.0 * collision_r);
  w.particles.angular_velocity[0] = 3.0; // spin so friction acts from the start
  w.particles.mass[1] *= 2.0;            // unequal grains: nothing cancels by symmetry
  w.particles.inv_mass[1] /= 2.0;
  const SimulationConfig c = config_for(w, GetParam().integrator, GetParam().law);
  Simulation s(std::move(w), c);
  const Vec2 p0 = linear_momentum(s);
  const Vec2 pivot{0.3, -0.7}; // angular momentum about an arbitrary point
  const double l0 = angular_momentum(s, pivot);
  const double e0 = energies(s).total();
  const double p_scale = 2.0 * s.world().particles.mass[0] * v;
  const double l_scale = std::abs(l0) + p_scale * 1.0;
  double worst_p = 0.0, worst_l = 0.0;
  const auto rec = collide(s, 100000, testing::overlap01, [&](const Simulation& sim) {
    worst_p = std::max(worst_p, norm(linear_momentum(sim) - p0) / p_scale);
    worst_l = std::max(worst_l, std::abs(angular_momentum(sim, pivot) - l0) / l_scale);
  });
  ASSERT_TRUE(rec.separated);
  EXPECT_LT(energies(s).total(), 0.5 * e0); // strongly dissipative
  EXPECT_LT(worst_p, reference::roundoff_tolerance);
  if (GetParam().integrator == Integrator::verlet) {
    EXPECT_LT(worst_l, reference::roundoff_tolerance);
  } else {
    EXPECT_LT(worst_l, reference::gear_angular_momentum_tolerance);
  }
}

// Gear's Taylor predictor does not preserve r x v exactly, so its angular momentum error is a
// truncation error: it must shrink as dt^2 (the measured order; a factor 4 per halving).
TEST(DissipativeFrictionalCollisionGear, AngularMomentumErrorConvergesAtSecondOrder) {
  const auto worst_at = [](double steps_per_collision) {
    Material m = elastic_material();
    m.restitution = 0.3;
    m.friction = 0.5;
    m.tangential_damping = 500.0;
    World w = two_grains(m, collision_r, 2.0 * reference::thesis_disk_speed, collision_r);
    w.particles.angular_velocity[0] = 3.0;
    const SimulationConfig c =
        config_for(w, Integrator::gear, law_id<CundallStrack>, steps_per_collision);
    Simulation s(std::move(w), c);
    const double l0 = angular_momentum(s, {0.3, -0.7});
    double worst = 0.0;
    collide(s, 100000, testing::overlap01, [&](const Simulation& sim) {
      worst = std::max(worst, std::abs(angular_momentum(sim, {0.3, -0.7}) - l0) / std::abs(l0));
    });
    return worst;
  };
  const double ratio = worst_at(100.0) / worst_at(200.0);
  EXPECT_NEAR(ratio, 4.0, 4.0 * 0.25) << "error ratio when dt halves";
}

INSTANTIATE_TEST_SUITE_P(LawsAndIntegrators, DissipativeFrictionalCollision,
                         ::testing::Values(LossyCase{Integrator::verlet, law_id<ViscousCoulomb>},
                                           LossyCase{Integrator::verlet, law_id<CundallStrack>},
                                           LossyCase{Integrator::gear, law_id<ViscousCoulomb>},
                                           LossyCase{Integrator::gear, law_id<CundallStrack>}),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param.integrator)) + "_" +
                                  std::string(name_of(param_info.param.law));
                         });

} // namespace
} // namespace talus
