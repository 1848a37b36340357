// The energy ledger of a run of spheres (analysis/energy_ledger3.hpp): a head-on impact's
// damper dissipates what the restitution's closed form takes, and the balance
// E_total + dissipated - plate work stays at its start within the integration's error on a bed
// shaken by a vibrating floor (friction and rolling resistance) and for a sphere carried by a
// turning floor, with both integrators. Tolerances are stated where they are used.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/energy_ledger3.hpp"
#include "support/shaken_bed3.hpp"
#include "support/two_body.hpp"

namespace talus {
namespace {

// Two spheres meeting head on along x at relative speed v, with restitution e: the normal
// damper dissipates 1/2 m_eff v^2 (1 - e^2), the linear law's never-attractive dashpot reaching
// e exactly (docs/model.md). 5e-3: at 200 steps a collision both integrators reach e within
// about 2e-3 (test_spheres_3d.cpp's impacts allow 1%), which moves 1 - e^2 by about as much. The
// balance against the kinetic energy the integrators did lose holds within 1e-3: the
// trapezoids' error on the power, O(dt^2).
TEST(EnergyLedger3, AHeadOnImpactDissipatesWhatTheRestitutionTakes) {
  for (const Integrator integrator : {Integrator::verlet, Integrator::gear}) {
    const double r = 1e-3, v = 0.2, e = 0.6;
    Material m = testing::elastic_material();
    m.restitution = e;
    Scene3 scene;
    scene.materials = {m};
    scene.add_sphere({.position = {1.01 * r, 0.0, 0.0}, .radius = r, .velocity = {-0.5 * v, 0, 0}});
    scene.add_sphere({.position = {-1.01 * r, 0.0, 0.0}, .radius = r, .velocity = {0.5 * v, 0, 0}});
    const double m_eff = 0.5 * scene.spheres.mass[0];
    const double tc = linear_collision_time(m.normal_stiffness, 0.0, m_eff);
    Simulation3 sim(std::move(scene), {.timestep = tc / 200.0, .integrator = integrator});
    EnergyLedger ledger;
    start_ledger(ledger, sim);
    for (int k = 0; k < 800; ++k) {
      sim.step();
      observe_ledger(ledger, sim);
    }
    ASSERT_EQ(sim.contact_count(), 0u) << "the spheres have not parted";
    const LedgerRow row = ledger_row(ledger, sim.energies());
    const double closed_form = 0.5 * m_eff * v * v * (1.0 - e * e);
    EXPECT_NEAR(row.dissipated_damper, closed_form, 5e-3 * closed_form);
    EXPECT_NEAR(row.imbalance, 0.0, 1e-3 * closed_form);
    EXPECT_EQ(row.wall_work, 0.0);
  }
}

// Runs `steps` with the ledger and returns its last row; the largest |imbalance| on the way is
// `worst`.
LedgerRow run_with_ledger(Simulation3& sim, int steps, double& worst) {
  EnergyLedger ledger;
  start_ledger(ledger, sim);
  LedgerRow row;
  worst = 0.0;
  for (int k = 1; k <= steps; ++k) {
    sim.step();
    observe_ledger(ledger, sim);
    if (k % 100 == 0) {
      row = ledger_row(ledger, sim.energies());
      worst = std::max(worst, std::abs(row.imbalance));
    }
  }
  return row;
}

// The bed of support/shaken_bed3.hpp, its floor vibrating with an amplitude of 0.4 mm (4 g), 50
// steps a collision: the energy released by the fall and put in by the floor goes to the dampers
// and friction. As for the 2D engine's frictional silo (tests/scenario/test_energy_ledger.cpp):
// Gear's imbalance stays within 5e-4 of the dissipated energy, velocity Verlet's within 5e-3
// (its damping and friction see the velocity a step behind: first order).
TEST(EnergyLedger3, AShakenBedBalancesThePlatesWorkAgainstDissipation) {
  for (const auto& [integrator, tolerance] :
       {std::pair{Integrator::gear, 5e-4}, {Integrator::verlet, 5e-3}}) {
    Simulation3 sim = testing::shaken_bed3(integrator, 4e-4, 50.0);
    double worst = 0.0;
    const LedgerRow row = run_with_ledger(sim, 20000, worst);
    const double dissipated = row.dissipated_damper + row.dissipated_friction;
    EXPECT_GT(row.dissipated_friction, 0.0);
    EXPECT_GT(row.dissipated_damper, 0.0);
    EXPECT_LT(worst, tolerance * dissipated)
        << "imbalance " << row.imbalance << " J of " << dissipated << " J dissipated, "
        << row.wall_work << " J put in by the floor";
    // the floor's work, left out, would be far beyond the tolerance
    EXPECT_GT(row.wall_work, 10.0 * tolerance * dissipated);
  }
}

// A sphere at rest on a floor turning about z, off its axis: friction (and rolling resistance)
// carry it round, the floor's work going to its motion and to friction. 5e-4 of the work:
// velocity Verlet's first-order error while the sphere, set down a little into the floor, bounces
// and settles.
TEST(EnergyLedger3, ATurningFloorsWorkGoesToTheSphereAndToFriction) {
  Material m = testing::elastic_material();
  m.restitution = 0.5;
  m.friction = 0.3;
  m.rolling_friction = 0.02;
  Scene3 scene;
  scene.materials = {m};
  scene.gravity = {0.0, 0.0, -9.81};
  scene.plates.push_back(make_plane({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}));
  scene.drivers.push_back(
      {.plate = 0, .motion = PlateDriver::Motion::rotate, .angular_velocity = {0.0, 0.0, 20.0}});
  const double r = 1e-3;
  scene.add_sphere({.position = {0.01, 0.0, 0.999 * r}, .radius = r});
  const double mass = scene.spheres.mass[0];
  Simulation3 sim(std::move(scene),
                  {.timestep = linear_collision_time(m.normal_stiffness, 0.0, mass) / 50.0});
  double worst = 0.0;
  const LedgerRow row = run_with_ledger(sim, 20000, worst);
  const Energies3 e = sim.energies();
  EXPECT_GT(e.kinetic, 0.1 * row.wall_work) << "the sphere was not carried round";
  EXPECT_GT(row.dissipated_friction, 0.0);
  EXPECT_LT(worst, 5e-4 * row.wall_work) << "imbalance " << row.imbalance << " J";
}

} // namespace
} // namespace talus
