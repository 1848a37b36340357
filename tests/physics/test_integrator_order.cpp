// Gear and Verlet show their order of accuracy on a harmonic oscillator: a grain bouncing gently
// on a linear floor contact under gravity, never leaving it (so the force stays smooth).
#include <gtest/gtest.h>

#include <cmath>

#include "integrate/integrator.hpp"
#include "physics/reference_values.hpp"
#include "support/two_body.hpp"

namespace talus {
namespace {

// Position error after 2 1/4 periods (where cos has its steepest slope, so a phase error shows
// linearly) with `steps` steps per period.
double oscillator_error(Integrator integrator, double steps) {
  const double r = 1.0e-3, k = 1.0e4, g = 9.81;
  Material m = testing::elastic_material(k);
  World w;
  w.materials = {m};
  w.gravity = {0.0, -g};
  w.add_wall({-1.0, 0.0}, {1.0, 0.0});
  const double mass = shape_mass(Shape::disk, r, m.density);
  const double sag = mass * g / k, amplitude = 0.5 * sag;
  w.add_particle({.position = {0.0, r - sag + amplitude}, .radius = r});
  const double omega = std::sqrt(k / mass), period = 2.0 * std::numbers::pi / omega;
  SimulationConfig c;
  c.timestep = period / steps;
  c.integrator = integrator;
  c.tangential_law = law_id<ViscousCoulomb>;
  Simulation s(std::move(w), c);
  s.run(static_cast<std::uint64_t>(std::llround(2.25 * steps)));
  const double exact = r - sag + amplitude * std::cos(omega * s.time());
  return std::abs(s.world().particles.position[0].y - exact) / amplitude;
}

TEST(IntegratorOrder, VerletIsSecondOrder) {
  const double ratio =
      oscillator_error(Integrator::verlet, 100) / oscillator_error(Integrator::verlet, 200);
  EXPECT_NEAR(ratio, reference::verlet_error_ratio,
              reference::verlet_error_ratio * reference::order_tolerance);
}

TEST(IntegratorOrder, GearShowsItsOrder) {
  const double e1 = oscillator_error(Integrator::gear, 100);
  const double e2 = oscillator_error(Integrator::gear, 200);
  EXPECT_NEAR(e1 / e2, reference::gear_error_ratio,
              reference::gear_error_ratio * reference::order_tolerance)
      << "errors " << e1 << " and " << e2;
  // and at equal cost Gear is the more accurate of the two here
  EXPECT_LT(e1, oscillator_error(Integrator::verlet, 100));
}

} // namespace
} // namespace talus

namespace talus {
namespace {

// Largest stable timestep: a grain pressed between two fixed grains oscillates undamped.
double amplitude_growth(Integrator integrator, double fraction_of_bound, int steps) {
  const double r = 1.0e-3, k = 1.0e4;
  Material m = testing::elastic_material(k);
  World w;
  w.materials = {m};
  w.add_particle({.position = {-1.99e-3, 0.0}, .radius = r, .kind = Kind::fixed});
  w.add_particle({.position = {1.99e-3, 0.0}, .radius = r, .kind = Kind::fixed});
  w.add_particle({.position = {1e-7, 0.0}, .radius = r}); // 1% of the overlaps: in contact
  const double mass = w.particles.mass[2];
  SimulationConfig c;
  // two springs in parallel: stiffness 2k on the grain (m_eff = m against fixed grains)
  c.timestep = fraction_of_bound * max_stable_timestep(integrator, 2.0 * k, mass);
  c.integrator = integrator;
  c.tangential_law = law_id<ViscousCoulomb>;
  c.max_overlap_fraction = 1e9; // let it grow: this test measures the growth
  Simulation s(std::move(w), c);
  double peak = 0.0;
  s.run(static_cast<std::uint64_t>(steps), [&](const Simulation& sim) {
    peak = std::max(peak, std::abs(sim.world().particles.position[2].x));
  });
  return peak / 1e-7;
}

TEST(StableTimestep, VerletBoundIsSharp) {
  EXPECT_LT(amplitude_growth(Integrator::verlet, 0.95, 2000), 10.0);
  EXPECT_GT(amplitude_growth(Integrator::verlet, 1.05, 2000), 50.0); // grows until it leaves
}

TEST(StableTimestep, GearStaysBoundedAtItsBound) {
  EXPECT_LT(amplitude_growth(Integrator::gear, 1.0, 2000), 1.05);
  EXPECT_GT(amplitude_growth(Integrator::gear, 3.0, 2000), 1.5); // and it is a real bound
}

} // namespace
} // namespace talus
