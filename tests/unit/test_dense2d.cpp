// The benchmark system matches the LAMMPS input it is compared with (bench/lammps).
#include <gtest/gtest.h>

#include <numbers>

#include "scenario/dense2d.hpp"

namespace talus {
namespace {

TEST(Dense2d, MatchesTheLammpsInput) {
  const Dense2d d = build_dense2d(10, 8);
  const Particles& p = d.world.particles;
  ASSERT_EQ(p.size(), 80U);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_GE(2.0 * p.radius[i], 0.0085);
    EXPECT_LE(2.0 * p.radius[i], 0.0095);
    const double r = p.radius[i];
    EXPECT_NEAR(p.mass[i], 4.0 / 3.0 * std::numbers::pi * r * r * r * 1000.0, 1e-15); // sphere mass
    EXPECT_NEAR(p.inertia[i], 0.5 * p.mass[i] * r * r, 1e-18); // disc inertia
  }
  EXPECT_TRUE(d.world.domain.periodic_x);
  EXPECT_FALSE(d.world.domain.periodic_y);
  EXPECT_DOUBLE_EQ(d.world.domain.size().x, 0.1);
  const Material& m = d.world.materials[0];
  EXPECT_DOUBLE_EQ(m.normal_stiffness, 1e5);
  EXPECT_DOUBLE_EQ(m.normal_damping_rate, 100.0);
  EXPECT_DOUBLE_EQ(m.tangential_damping, 50.0);
  EXPECT_DOUBLE_EQ(m.friction, 0.5);
  EXPECT_DOUBLE_EQ(d.config.timestep, 1e-5);
  EXPECT_DOUBLE_EQ(d.config.skin, 1e-3);
  EXPECT_EQ(d.config.integrator, Integrator::verlet);
}

} // namespace
} // namespace talus
