// An elastic, frictionless gas of 1000 disks in a periodic box keeps its energy over 1e5 steps.
#include <gtest/gtest.h>

#include <cmath>

#include "core/random.hpp"
#include "materials/timestep.hpp"
#include "physics/reference_values.hpp"
#include "support/two_body.hpp"

namespace talus {
namespace {

World elastic_gas(std::size_t n, double r, double area_fraction, std::uint64_t seed) {
  World w;
  w.materials = {testing::elastic_material(1.0e4)};
  const double side = std::sqrt(static_cast<double>(n) * std::numbers::pi * r * r / area_fraction);
  w.domain = {{0.0, 0.0}, {side, side}, true, true};
  const auto per_row = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  const double pitch = side / static_cast<double>(per_row);
  RandomStream rng(seed, 7);
  for (std::size_t k = 0; k < n; ++k) {
    const double angle = 2.0 * std::numbers::pi * rng.uniform();
    const double speed = 0.05 * (0.5 + rng.uniform());
    w.add_particle({.position = {pitch * (static_cast<double>(k % per_row) + 0.5),
                                 pitch * (static_cast<double>(k / per_row) + 0.5)},
                    .radius = r * (0.9 + 0.2 * rng.uniform()),
                    .velocity = {speed * std::cos(angle), speed * std::sin(angle)}});
  }
  return w;
}

TEST(ElasticGas, EnergyDriftsLessThanTenToMinusFourOverTenToFiveSteps) {
  const double r = 1.0e-3;
  World w = elastic_gas(1000, r, 0.05, 3);
  const double m_min = shape_mass(Shape::disk, 0.9 * r, w.materials[0].density);
  SimulationConfig c;
  // a dilute gas: few grains in contact at once. Each collision's energy error comes from the
  // force's kink at first touch (2e-4 of the pair's energy at t_c / 50), with either sign, so the
  // drift over 1e5 steps is a random walk whose value depends on the trajectory to the last bit:
  // at t_c / 50 of the lightest pair it came out between 6e-6 and 1.05e-4 for five seeds and
  // five skins (the skin moves the periodic wraps), at t_c / 100 between 3e-6 and 9e-6, which
  // is what this test uses, to test the integrator and not one trajectory's luck.
  c.timestep = linear_collision_time(1.0e4, 0.0, 0.5 * m_min) / 100.0;
  c.integrator = Integrator::verlet;
  c.tangential_law = law_id<ViscousCoulomb>;
  Simulation s(std::move(w), c);
  const double e0 = energies(s).total();
  const Vec2 p0 = linear_momentum(s);
  s.run(100'000);
  const double drift = std::abs(energies(s).total() - e0) / e0;
  EXPECT_LT(drift, reference::gas_drift_tolerance);
  // momentum is conserved to round-off across periodic boundaries too
  EXPECT_LT(norm(linear_momentum(s) - p0), reference::roundoff_tolerance * norm(p0) * 1e3);
  RecordProperty("energy_drift", std::to_string(drift));
}

} // namespace
} // namespace talus
