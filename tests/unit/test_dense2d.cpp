// The benchmark system matches the LAMMPS input it is compared with (inputs/dense2d).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/random.hpp"
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

// Copies of a settled packing side by side are the same packing, wider: each copy moves as the
// base does. The base is settled for 0.1 s first so that its contacts carry tangential history,
// which the copies must inherit: without it their grains would slip at once (checked below).
TEST(Dense2d, TiledCopiesMoveAsTheBaseDoes) {
  Dense2d d = build_dense2d(12, 10);
  RandomStream rng(7, 1); // stir the lattice so that the grains rub as they settle
  for (Vec2& v : d.world.particles.velocity) v = {rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2)};
  Simulation settle(std::move(d.world), d.config);
  settle.run(10'000);
  const SimulationState base = settle.state();
  const std::size_t n = base.world.particles.size();
  const std::size_t copies = 3;
  Simulation wide = Simulation::restore(tile_dense2d(base, copies, d.config.skin), d.config);
  Simulation alone = Simulation::restore(base, d.config);
  ASSERT_EQ(wide.world().particles.size(), copies * n);
  EXPECT_DOUBLE_EQ(wide.world().domain.size().x, copies * base.world.domain.size().x);
  const auto sum_s2 = [](const NeighbourList& l) {
    double sum = 0.0;
    for (const double s : l.history) sum += s * s;
    return sum;
  };
  // the base holds shear in its springs (about 1 um rms per grain; at least 0.1 um asked); each
  // copy holds the same (pairs the rebuilt list adds or drops do not touch: their history is 0)
  ASSERT_GT(sum_s2(base.neighbours), 1e-14 * static_cast<double>(n));
  EXPECT_NEAR(sum_s2(wide.neighbours()) / copies, sum_s2(base.neighbours),
              1e-12 * sum_s2(base.neighbours));
  wide.run(500);
  alone.run(500);
  // The copies differ from the base only by round-off (positions are shifted by whole widths):
  // about 1e-12 m after 500 steps, so 1e-10 m; without the history they move by about 1e-4 m.
  // Matched by id, as both runs renumber their particles (sort_interval): the copy particle
  // with id q copies the base's particle q % n, which has id base.id[q % n] in `alone`.
  const Particles& a = alone.world().particles;
  const Particles& w = wide.world().particles;
  ASSERT_GT(alone.renumberings(), 0U);
  std::vector<std::size_t> index_of_id(n);
  for (std::size_t i = 0; i < n; ++i) index_of_id[a.id[i]] = i;
  const double width = base.world.domain.size().x;
  double worst = 0.0;
  for (std::size_t k = 0; k < w.size(); ++k) {
    const std::size_t i = index_of_id[base.world.particles.id[w.id[k] % n]];
    double dx = w.position[k].x - a.position[i].x;
    dx -= width * std::round(dx / width);
    worst = std::max({worst, std::abs(dx), std::abs(w.position[k].y - a.position[i].y)});
  }
  EXPECT_LT(worst, 1e-10);
}

} // namespace
} // namespace talus
