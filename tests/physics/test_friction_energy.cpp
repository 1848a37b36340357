// Friction that never creates energy (tangential_laws.hpp's spring rule): a sliding contact's
// force never points along the slip, no step's friction dissipation is negative beyond the
// ledger's integration error, and the ledger stays balanced, for every spring law with both
// normal laws, on disks and on spheres moving in a plane. With them the closed forms of a sticking
// impact, which only the incremental spring meets once the stiffness follows the overlap, and the
// tangential dashpot derived from the restitution (Tsuji et al. 1992).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "analysis/energy_ledger.hpp"
#include "analysis/observables.hpp"
#include "physics/reference_values.hpp"
#include "physics/single_impact.hpp"
#include "simulation/simulation.hpp"
#include "talus/law_table.hpp"

namespace talus {
namespace {

namespace ref = reference;
using namespace single_impact;

struct Watch {
  double worst_step_dissipation = 0.0; ///< the most negative step of friction's dissipation, J
  double largest_spring_energy = 0.0;  ///< J
  bool pushed_along_slip = false;
  bool slip_speed_rose = false;
  double final_imbalance = 0.0;
  double dissipated_friction = 0.0;
  bool separated = false;
};

// Steps through the impact and a little past it, with the energy ledger looking at every step.
Watch watch(Simulation& s, LeverArm arm) {
  Watch out;
  EnergyLedger ledger;
  start_ledger(ledger, s);
  double previous_friction = 0.0, previous_slip = std::abs(slip(s, arm));
  bool touched = false;
  const double mu = s.world().materials[0].friction;
  for (int k = 0; k < 1'000'000 && !out.separated; ++k) {
    s.step();
    observe_ledger(ledger, s);
    const LedgerRow row = ledger_row(ledger, energies(s));
    out.worst_step_dissipation =
        std::min(out.worst_step_dissipation, row.dissipated_friction - previous_friction);
    previous_friction = row.dissipated_friction;
    out.largest_spring_energy =
        std::max(out.largest_spring_energy, contact_powers(s).tangential_elastic);
    const Vec2 f = s.world().particles.force[0];
    const double u = slip(s, arm);
    const bool sliding = f.y > 0.0 && std::abs(f.x) >= mu * f.y * (1.0 - 1e-9);
    if (sliding && f.x * u > 0.0) out.pushed_along_slip = true;
    if (sliding && std::abs(u) > previous_slip * (1.0 + 1e-12)) out.slip_speed_rose = true;
    previous_slip = std::abs(u);
    touched = touched || gap(s) < 0.0;
    out.separated = touched && gap(s) > 0.0;
    out.final_imbalance = row.imbalance;
    out.dissipated_friction = row.dissipated_friction;
  }
  return out;
}

Material aluminium() {
  Material m;
  m.name = "aluminium";
  m.density = 2700.0;
  m.young = 7.0e10;
  m.poisson = 0.33;
  m.restitution = 0.5;
  m.hertz_damping = -1.0; // from the restitution
  m.friction = 0.4;
  m.tangential_damping = 1900.0;
  return m;
}

// The case that showed the old reset's defect: an aluminium sphere (R = 0.1 m) at 0.2 m/s onto a
// rigid floor, spun so that its contact slides at 0.76 m/s, mu = 0.4, e = 0.5 and a tangential
// dashpot of 1900 1/s, Hertz with either spring law. In sliding the force must oppose the slip,
// so the slip speed can only fall; the spring never holds more than the grain's kinetic energy.
TEST(FrictionEnergy, ASlidingContactNeverPushesAlongTheSlip) {
  for (TangentialLaw t : {law_id<CundallStrack>, law_id<MindlinNoSlip>}) {
    SCOPED_TRACE(std::string(name_of(t)));
    Impact c{.grain = aluminium(), .tangential = t, .velocity = {0.0, -0.2}, .spin = 7.6};
    Simulation s = impact(c);
    const double kinetic = energies(s).kinetic();
    const Watch w = watch(s, c.arm);
    ASSERT_TRUE(w.separated);
    EXPECT_FALSE(w.pushed_along_slip);
    EXPECT_FALSE(w.slip_speed_rose);
    EXPECT_LT(w.largest_spring_energy, kinetic);
    EXPECT_GT(w.dissipated_friction, 0.0);
    EXPECT_GE(w.worst_step_dissipation, -ref::friction_step_tolerance * kinetic);
  }
}

// Random oblique impacts: both normal laws, every tangential law with friction, disks and
// spheres, restitution, friction, spin and tangential damping (none, a rate, or from the
// restitution) drawn at random. No step's friction dissipation is below minus the ledger's
// integration error, and the ledger balances at the end.
TEST(FrictionEnergy, RandomObliqueImpactsNeverCreateEnergyInFriction) {
  std::mt19937_64 random(20261204);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const TangentialLaw laws[] = {law_id<CundallStrack>, law_id<MindlinNoSlip>,
                                law_id<ViscousCoulomb>};
  for (int trial = 0; trial < 48; ++trial) {
    Impact c;
    c.normal = trial % 2 == 0 ? law_id<HertzViscoelastic> : law_id<LinearSpringDashpot>;
    c.tangential = laws[(trial / 2) % 3];
    c.shape = (trial / 6) % 2 == 0 ? Shape::sphere : Shape::disk;
    c.radius = 1e-3;
    c.grain = aluminium();
    c.grain.young = 1e8;
    c.grain.normal_stiffness = 1e4;
    c.grain.restitution = 0.3 + 0.7 * unit(random);
    c.grain.friction = 0.05 + 0.95 * unit(random);
    const int damping = (trial / 12) % 3;
    const bool spring = c.tangential != law_id<ViscousCoulomb>;
    c.grain.tangential_damping =
        damping == 0 ? 0.0 : (damping == 1 || !spring ? 1e3 * unit(random) : -1.0);
    const double angle = 0.5 * std::numbers::pi * unit(random);
    const double speed = 0.02 + 0.1 * unit(random);
    c.velocity = {speed * std::cos(angle) * (unit(random) < 0.5 ? -1.0 : 1.0),
                  -speed * (std::sin(angle) + 0.05)};
    c.spin = (unit(random) - 0.5) * 4.0 * speed / c.radius;
    SCOPED_TRACE("trial " + std::to_string(trial) + ": " + std::string(name_of(c.normal)) + ", " +
                 std::string(name_of(c.tangential)));
    Simulation s = impact(c);
    const double kinetic = energies(s).kinetic();
    const Watch w = watch(s, c.arm);
    ASSERT_TRUE(w.separated);
    EXPECT_GE(w.worst_step_dissipation, -ref::friction_step_tolerance * kinetic);
    EXPECT_LE(std::abs(w.final_imbalance), ref::impact_balance_tolerance * kinetic);
  }
}

// A grain on a floor that shakes sideways (10 Hz, the grain pressed by gravity): stick and slip
// alternate for a second, some 20 reversals. Friction's dissipation, as the ledger integrates it
// (trapezoids on the power, looked at after each step), never falls by more than a step's share
// of the work at a reversal, where the force turns within a step; the energy the floor puts in is
// what friction and the dampers took, but for the integration's error.
TEST(FrictionEnergy, ALongStickSlipShearNeverCreatesEnergy) {
  for (NormalLaw n : {law_id<LinearSpringDashpot>, law_id<HertzViscoelastic>}) {
    for (TangentialLaw t : {law_id<CundallStrack>, law_id<MindlinNoSlip>}) {
      SCOPED_TRACE(std::string(name_of(n)) + ", " + std::string(name_of(t)));
      Material m = aluminium();
      m.young = 1e8;
      m.normal_stiffness = 1e4;
      m.tangential_damping = -1.0;
      m.friction = 0.3;
      World w;
      w.materials = {m};
      const double r = 2e-3;
      w.add_particle({.position = {0.0, r}, .radius = r, .shape = Shape::disk});
      w.add_wall({-0.1, 0.0}, {0.1, 0.0}, 0);
      w.gravity = {0.0, -9.81};
      Driver d;
      d.motion = Vibrate{.direction = {1.0, 0.0}, .amplitude = 2e-3, .frequency = 10.0};
      d.targets.segments = {0};
      attach(d, w);
      w.drivers.push_back(d);
      SimulationConfig config;
      config.normal_law = n;
      config.tangential_law = t;
      config.impact_speed = 0.1;
      config.timestep = 2e-5;
      Simulation s(std::move(w), config);
      EnergyLedger ledger;
      start_ledger(ledger, s);
      double previous = 0.0, worst = 0.0, scale = 0.0;
      LedgerRow row;
      for (int k = 0; k < 50'000; ++k) {
        s.step();
        observe_ledger(ledger, s);
        row = ledger_row(ledger, energies(s));
        worst = std::min(worst, row.dissipated_friction - previous);
        previous = row.dissipated_friction;
        scale = std::max(scale, row.dissipated_friction);
      }
      EXPECT_GT(row.dissipated_friction, 0.0);
      EXPECT_GE(worst, -ref::shear_step_tolerance * scale);
      EXPECT_LE(std::abs(row.imbalance), ref::shear_balance_tolerance * row.wall_work);
    }
  }
}

// The continuous model of an elastic sticking impact with Hertz and Cundall-Strack's spring
// (k_t = kappa k_n', k_n' = 3/2 rho sqrt(xi)), integrated by RK4 in 1e5 steps: loading,
// dF_t/dt = -k_t u; unloading, the stretch s = -F_t / k_t kept, ds/dt = u; u' = F_t / m_t. The
// contact point's tangential velocity when the overlap ends, over its value at the touch.
double hertz_sticking_reference(double rho, double kappa, double m, double m_t, double v0,
                                double u0) {
  struct State {
    double xi, rate, spring, u; // spring: F_t while loading, s while unloading
  };
  bool loading = true;
  const auto k_t = [&](double xi) { return kappa * 1.5 * rho * std::sqrt(std::max(xi, 0.0)); };
  const auto derivative = [&](const State& y) {
    const double xi = std::max(y.xi, 0.0), kt = k_t(xi);
    const double ft = loading ? y.spring : -kt * y.spring;
    return State{y.rate, -rho * xi * std::sqrt(xi) / m, loading ? -kt * y.u : y.u, ft / m_t};
  };
  const double t_c = hertz_collision_time(m, rho, v0);
  const int steps = 100000;
  const double h = 1.2 * t_c / steps;
  State y{0.0, v0, 0.0, u0};
  for (int k = 0; k < steps && y.xi >= 0.0; ++k) {
    if (loading && y.rate < 0.0) { // from the force to the stretch it holds
      loading = false;
      y.spring = -y.spring / k_t(y.xi);
    }
    const auto step = [&](const State& a, const State& d, double f) {
      return State{a.xi + f * d.xi, a.rate + f * d.rate, a.spring + f * d.spring, a.u + f * d.u};
    };
    const State k1 = derivative(y), k2 = derivative(step(y, k1, h / 2));
    const State k3 = derivative(step(y, k2, h / 2)), k4 = derivative(step(y, k3, h));
    y = State{y.xi + h / 6 * (k1.xi + 2 * k2.xi + 2 * k3.xi + k4.xi),
              y.rate + h / 6 * (k1.rate + 2 * k2.rate + 2 * k3.rate + k4.rate),
              y.spring + h / 6 * (k1.spring + 2 * k2.spring + 2 * k3.spring + k4.spring),
              y.u + h / 6 * (k1.u + 2 * k2.u + 2 * k3.u + k4.u)};
  }
  return y.u / u0;
}

// Elastic and sticking (mu large), a grain whose tangential spring is Cundall-Strack's at
// kappa = k_t / k_n' = m_t / m, m_t = 1 / (1/m + R^2 / I) the contact point's tangential mass
// (2/7 m for a sphere, 1/3 m for a disk; lever arms at the radius).
// - Linear law: the contact point's tangential velocity turns as cos(omega_t t) with omega_t
//   = omega_n, so the grain leaves with u' = -u0 exactly (Maw, Barber & Fawcett 1976's
//   tangential mass; Cundall & Strack 1979's spring).
// - Hertz: the spring follows the overlap; the rebound is the continuous model's, integrated
//   apart (above). Loading alone would give -u0 too (u and xi' then obey the same equation);
//   the stretch kept while unloading lets the force fall with the stiffness, and the grain
//   leaves with less.
// The tolerance: the spring's stretch is summed with the slip at each step's end, first order
// in the step (reference_values.hpp).
TEST(FrictionEnergy, AnElasticStickingImpactTurnsTheContactVelocityAsTheModelSays) {
  for (NormalLaw n : {law_id<LinearSpringDashpot>, law_id<HertzViscoelastic>}) {
    for (Shape shape : {Shape::sphere, Shape::disk}) {
      SCOPED_TRACE(std::string(name_of(n)) + (shape == Shape::sphere ? ", sphere" : ", disk"));
      Material m = aluminium();
      m.young = 1e8;
      m.normal_stiffness = 1e4;
      m.restitution = 1.0;
      m.hertz_damping = 0.0;
      m.tangential_damping = 0.0;
      m.friction = 1e3;
      const double kappa = shape == Shape::sphere ? 2.0 / 7.0 : 1.0 / 3.0;
      m.tangential_stiffness_ratio = kappa;
      Impact c{.grain = m,
               .normal = n,
               .shape = shape,
               .radius = 1e-3,
               .velocity = {0.02, -0.1},
               .steps_per_collision = ref::sticking_steps_per_collision,
               .arm = LeverArm::radius};
      Simulation s = impact(c);
      const double u0 = slip(s, c.arm), mass = s.world().particles.mass[0];
      ASSERT_TRUE(watch(s, c.arm).separated);
      const double rho = hertz_rho(m.young / (1.0 - m.poisson * m.poisson), c.radius);
      const double expected =
          n == law_id<LinearSpringDashpot>
              ? -1.0
              : hertz_sticking_reference(rho, kappa, mass, kappa * mass, 0.1, u0);
      EXPECT_NEAR(slip(s, c.arm) / u0, expected, ref::sticking_reversal_tolerance);
    }
  }
}

// Gross sliding (Maw, Barber & Fawcett 1976's sliding regime; the rigid-body theory of an impact
// with Coulomb friction): a grain whose contact point slides throughout the impact takes a
// tangential impulse of mu times the normal one, against the slip. With J_n = m (v_n' - v_n) as
// the run made it, v_t' = v_t - mu J_n / m and w' = w - mu J_n R / I (the slip along +x; lever
// arms at the radius). Every friction law, both normal laws, disks and spheres, at 5 times the
// normal speed along the floor: the spring laws reach the cone in the first step in contact and
// slide from then on, so the impulses hold to round-off. (Mindlin's spring beside the linear
// normal law is left out: its k_t starts from zero while mu F_n grows at once, so it sticks for a
// while first, 1.5e-2 of the impulse at these values.)
TEST(FrictionEnergy, AGrossSlidingImpactTakesMuTimesTheNormalImpulse) {
  for (NormalLaw n : {law_id<LinearSpringDashpot>, law_id<HertzViscoelastic>}) {
    for (TangentialLaw t : {law_id<CundallStrack>, law_id<MindlinNoSlip>, law_id<ViscousCoulomb>}) {
      if (n == law_id<LinearSpringDashpot> && t == law_id<MindlinNoSlip>) continue;
      for (Shape shape : {Shape::sphere, Shape::disk}) {
        SCOPED_TRACE(std::string(name_of(n)) + ", " + std::string(name_of(t)) +
                     (shape == Shape::sphere ? ", sphere" : ", disk"));
        Material m = aluminium();
        m.young = 1e8;
        m.normal_stiffness = 1e4;
        m.friction = 0.3;
        m.tangential_damping = t == law_id<ViscousCoulomb> ? 1e9 : 0.0; // always at the cap
        Impact c{.grain = m,
                 .normal = n,
                 .tangential = t,
                 .shape = shape,
                 .radius = 1e-3,
                 .velocity = {0.5, -0.1},
                 .arm = LeverArm::radius};
        Simulation s = impact(c);
        ASSERT_TRUE(watch(s, c.arm).separated);
        const auto& p = s.world().particles;
        const double mass = p.mass[0], inertia = p.inertia[0];
        const double normal_impulse = mass * (p.velocity[0].y - c.velocity.y);
        const double tangential_impulse = m.friction * normal_impulse;
        EXPECT_NEAR(p.velocity[0].x, 0.5 - tangential_impulse / mass,
                    ref::sliding_impulse_tolerance * tangential_impulse / mass);
        EXPECT_NEAR(p.angular_velocity[0], -tangential_impulse * c.radius / inertia,
                    ref::sliding_impulse_tolerance * tangential_impulse * c.radius / inertia);
      }
    }
  }
}

// The tangential dashpot from the restitution, for the linear law with Cundall-Strack: sticking,
// the contact point is a damped oscillator, m_t u' = -k_t x - eta_t u, eta_t = c sqrt(k_t m),
// c = 2 |ln e| / sqrt(ln^2 e + pi^2), for as long as the normal force lasts: the never-attractive
// force ends at t_f = (pi - 2 atan(beta / omega)) / omega, where the grain leaves the floor's
// friction behind. Then u' = u0 exp(-g t_f) (cos w t_f - g / w sin w t_f), g = eta_t / (2 m_t),
// w^2 = k_t / m_t - g^2.
TEST(FrictionEnergy, ADashpotFromTheRestitutionDampsAStickingImpactAsTheClosedFormSays) {
  Material m = aluminium();
  m.normal_stiffness = 1e4;
  m.restitution = 0.5;
  m.tangential_damping = -1.0;
  m.friction = 1e3;
  m.tangential_stiffness_ratio = 2.0 / 7.0;
  Impact c{.grain = m,
           .normal = law_id<LinearSpringDashpot>,
           .radius = 1e-3,
           .velocity = {0.02, -0.1},
           .steps_per_collision = ref::sticking_steps_per_collision,
           .arm = LeverArm::radius};
  Simulation s = impact(c);
  const double mass = s.world().particles.mass[0];
  const double u0 = slip(s, c.arm);
  ASSERT_TRUE(watch(s, c.arm).separated);
  // normal: eta_n from the restitution, as mixed
  const PairParameters p = mix(m, floor_of(m), 0.1);
  const double eta_n = p.normal_dashpot(mass);
  const double beta = eta_n / (2.0 * mass);
  const double omega = std::sqrt(m.normal_stiffness / mass - beta * beta);
  const double t_f = (std::numbers::pi - 2.0 * std::atan(beta / omega)) / omega;
  // tangential
  const double m_t = 2.0 / 7.0 * mass, k_t = 2.0 / 7.0 * m.normal_stiffness;
  const double eta_t = tangential_damping_from_restitution(0.5) * std::sqrt(k_t * mass);
  const double g = eta_t / (2.0 * m_t), w = std::sqrt(k_t / m_t - g * g);
  const double expected = std::exp(-g * t_f) * (std::cos(w * t_f) - g / w * std::sin(w * t_f));
  EXPECT_NEAR(slip(s, c.arm) / u0, expected, ref::sticking_reversal_tolerance);
}

// The spring rule alone, step by step, on random contacts: the overlap loads and unloads, the
// slip reverses, the normal force comes and goes. Each step's dissipation, the work the
// tangential force takes from the slip (-F_t v_t dt, the slip the spring integrates) less the
// spring's energy gained (1/2 k_t s^2 at this overlap against the last), is never negative but
// for round-off (1e-12 of the step's energies), and the force stays within mu F_n.
template <class N, class T> void check_dissipation_never_negative(const PairParameters& p) {
  std::mt19937_64 random(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  const double dt = 1e-6;
  ContactGeometry g;
  g.normal_x = 1.0;
  g.r_eff = 1e-3;
  g.m_eff = 1e-5;
  g.arm_i = g.arm_j = 1e-3;
  g.overlap = 1e-6;
  double s = 0.0, rate = 0.0, u = 0.0, worst = 0.0, energy_before = 0.0;
  for (int k = 0; k < 20000; ++k) {
    rate = 0.995 * rate + 2e-4 * noise(random);
    u = 0.99 * u + 2e-3 * noise(random);
    g.v_normal = -rate;
    g.overlap = std::max(0.0, g.overlap + rate * dt);
    if (g.overlap == 0.0) rate = std::abs(rate);
    g.v_tangent = u;
    const double fn = N::force(p, g);
    const double ft = T::template force<N>(p, g, fn, s, dt);
    const double energy = 0.5 * T::stiffness(p, g, N::stiffness(p, g)) * s * s;
    const double dissipated = -ft * u * dt - (energy - energy_before);
    worst = std::min(worst, dissipated / (std::abs(ft * u * dt) + energy + energy_before + 1e-300));
    EXPECT_LE(std::abs(ft), p.friction * fn * (1.0 + 1e-15) + 1e-300);
    energy_before = energy;
  }
  EXPECT_GE(worst, -1e-12);
}

TEST(FrictionEnergy, NoStepOfTheSpringRuleDissipatesLessThanNothing) {
  Material m = aluminium();
  m.young = 1e8;
  m.normal_stiffness = 1e4;
  m.friction = 0.3;
  for (double damping : {0.0, 500.0, -1.0}) {
    m.tangential_damping = damping;
    const PairParameters p = mix(m, m, 0.1);
    SCOPED_TRACE("tangential_damping " + std::to_string(damping));
    check_dissipation_never_negative<LinearSpringDashpot, CundallStrack>(p);
    check_dissipation_never_negative<LinearSpringDashpot, MindlinNoSlip>(p);
    check_dissipation_never_negative<HertzViscoelastic, CundallStrack>(p);
    check_dissipation_never_negative<HertzViscoelastic, MindlinNoSlip>(p);
  }
}

// A material asking for a dashpot from the restitution beside a law with no spring is refused.
TEST(FrictionEnergy, ADashpotFromTheRestitutionNeedsASpring) {
  Material m = aluminium();
  m.tangential_damping = -1.0;
  EXPECT_NE(material_error(law_id<LinearSpringDashpot>, law_id<ViscousCoulomb>, m), "");
  EXPECT_EQ(material_error(law_id<HertzViscoelastic>, law_id<MindlinNoSlip>, m), "");
}

} // namespace
} // namespace talus
