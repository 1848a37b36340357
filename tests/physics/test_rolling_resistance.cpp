// Rolling resistance (src/talus/rolling_resistance.hpp): a grain rolling on a floor decelerates,
// and rests on a slope or rolls down it, as the closed forms of reference_values.hpp say; the
// energy ledger balances with friction's dissipation never negative.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/energy_ledger.hpp"
#include "materials/timestep.hpp"
#include "physics/reference_values.hpp"
#include "support/two_body.hpp"

namespace talus {
namespace {

namespace ref = reference;

struct Floor {
  Shape shape = Shape::disk;
  Integrator integrator = Integrator::gear;
  double rolling_friction = 0.1;
  double slope = 0.0; ///< rad: gravity tilted by this much from the floor's normal
  double speed = 0.2; ///< m/s, rolling without slip from the start
};

const double roll_radius = 5.0e-3, g_roll = 9.81;

Simulation roll_on_floor(const Floor& f) {
  Material m = testing::elastic_material(1.0e6);
  m.restitution = 0.3; // settles the floor contact quickly
  m.friction = 0.8;    // never slides: the rolling torques stay far below the Coulomb cap
  m.tangential_damping = 0.0;
  m.rolling_friction = f.rolling_friction;
  World w;
  w.materials = {m};
  w.gravity = {g_roll * std::sin(f.slope), -g_roll * std::cos(f.slope)};
  w.add_wall({-10.0, 0.0}, {10.0, 0.0});
  const double mass = shape_mass(f.shape, roll_radius, m.density);
  const double sag = mass * g_roll * std::cos(f.slope) / m.normal_stiffness; // resting overlap
  w.add_particle({.position = {0.0, roll_radius - sag},
                  .radius = roll_radius,
                  .shape = f.shape,
                  .velocity = {f.speed, 0.0},
                  .angular_velocity = -f.speed / roll_radius});
  SimulationConfig c;
  c.timestep = linear_collision_time(m.normal_stiffness, 0.0, mass) / 50.0;
  c.normal_law = law_id<LinearSpringDashpot>;
  c.tangential_law = law_id<CundallStrack>;
  c.integrator = f.integrator;
  return Simulation(std::move(w), c);
}

double inertia_factor(Shape s) {
  return s == Shape::disk ? ref::disk_inertia_factor : ref::sphere_inertia_factor;
}

// Steps until time t.
void run_until(Simulation& s, double t) {
  while (s.time() < t) s.step();
}

class RollingOnAFloor : public ::testing::TestWithParam<Floor> {};

TEST_P(RollingOnAFloor, DeceleratesAsTheTorqueBalanceSays) {
  const Floor f = GetParam();
  Simulation s = roll_on_floor(f);
  const double a = f.rolling_friction * g_roll / (1.0 + inertia_factor(f.shape));
  const double t_stop = f.speed / a;
  const auto& p = s.world().particles;
  run_until(s, 0.25 * t_stop);
  const double t1 = s.time(), v1 = p.velocity[0].x;
  run_until(s, 0.75 * t_stop);
  const double measured = (v1 - p.velocity[0].x) / (s.time() - t1);
  EXPECT_NEAR(measured, a, ref::rolling_resistance_tolerance * a);
  // it stops and stays: the spring holds it where friction alone would let it roll on
  run_until(s, 1.5 * t_stop);
  EXPECT_LT(std::abs(p.velocity[0].x), 1e-3 * f.speed);
  EXPECT_LT(std::abs(p.angular_velocity[0]) * roll_radius, 1e-3 * f.speed);
}

TEST_P(RollingOnAFloor, RestsOnASlopeBelowItsAngleAndRollsDownAbove) {
  Floor f = GetParam();
  f.speed = 0.0;
  const double k = inertia_factor(f.shape);
  for (const double ratio : {0.8, 1.25}) { // tan alpha / mu_r
    f.slope = std::atan(ratio * f.rolling_friction);
    SCOPED_TRACE("tan(slope) / mu_r = " + std::to_string(ratio));
    Simulation s = roll_on_floor(f);
    const auto& p = s.world().particles;
    const double t = 0.2;
    run_until(s, 0.5 * t);
    const double t1 = s.time(), v1 = p.velocity[0].x;
    run_until(s, t);
    const double measured = (p.velocity[0].x - v1) / (s.time() - t1);
    const double expected =
        ratio < 1.0
            ? 0.0
            : g_roll * (std::sin(f.slope) - f.rolling_friction * std::cos(f.slope)) / (1.0 + k);
    // at rest: what is left of the springs' ringing as the grain settles on the slope, far
    // below what rolling down it freely would give
    const double scale = g_roll * std::sin(f.slope) / (1.0 + k);
    EXPECT_NEAR(measured, expected,
                ratio < 1.0 ? 1e-4 * scale : ref::rolling_resistance_tolerance * expected);
  }
}

TEST_P(RollingOnAFloor, TheLedgerBalancesAndFrictionNeverGivesEnergyBack) {
  const Floor f = GetParam();
  Simulation s = roll_on_floor(f);
  const double t_stop = f.speed * (1.0 + inertia_factor(f.shape)) / (f.rolling_friction * g_roll);
  EnergyLedger ledger;
  start_ledger(ledger, s);
  const Energies start = energies(s);
  double previous = 0.0, worst = 0.0;
  LedgerRow row;
  while (s.time() < 1.2 * t_stop) {
    s.step();
    observe_ledger(ledger, s);
    row = ledger_row(ledger, energies(s));
    worst = std::min(worst, row.dissipated_friction - previous);
    previous = row.dissipated_friction;
  }
  const double kinetic = start.kinetic();
  // the kinetic energy went into rolling friction (the normal damper takes a little as the
  // floor contact settles)
  EXPECT_NEAR(row.dissipated_friction, kinetic, 0.02 * kinetic);
  // 1e-6: the trapezoidal rule on powers that jump as the spring mobilises
  EXPECT_GE(worst, -1e-6 * kinetic);
  EXPECT_LE(std::abs(row.imbalance), 1e-3 * kinetic);
}

INSTANTIATE_TEST_SUITE_P(ShapesAndIntegrators, RollingOnAFloor,
                         ::testing::Values(Floor{Shape::disk, Integrator::gear},
                                           Floor{Shape::sphere, Integrator::verlet}),
                         [](const auto& param_info) {
                           return std::string(param_info.param.shape == Shape::disk ? "disk_"
                                                                                    : "sphere_") +
                                  std::string(to_string(param_info.param.integrator));
                         });

TEST(RollingResistance, NoneWhenEveryMaterialHasNone) {
  Floor f;
  f.rolling_friction = 0.0;
  Simulation s = roll_on_floor(f);
  run_until(s, 0.1);
  // friction alone keeps it rolling at its speed (but for the small slip of a lever arm a little
  // short of the radius, as the grain sinks into the floor); rolling resistance would have
  // slowed it by a third
  EXPECT_NEAR(s.world().particles.velocity[0].x, f.speed, 1e-3 * f.speed);
  EXPECT_TRUE(s.neighbours().rolling.empty());
}

} // namespace
} // namespace talus
