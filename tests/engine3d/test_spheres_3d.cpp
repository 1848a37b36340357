// The 3D engine (native/engine3d) against closed forms: a head-on impact's restitution and
// duration, a sphere sliding on a floor until it rolls (Poeschel & Schwager 2005, sec. 2.3);
// against itself turned by a random rotation (isotropy); and against the 2D engine's spheres
// moving in a plane. Tolerances are stated where they are used.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <tuple>

#include <Eigen/Geometry>

#include "engine3d/simulation3.hpp"
#include "physics/reference_values.hpp"
#include "physics/single_impact.hpp"
#include "support/two_body.hpp"
#include "talus/error.hpp"

namespace talus {
namespace {

Vec3 unit_at_random(std::mt19937& rng) {
  std::normal_distribution<double> g;
  const Vec3 v{g(rng), g(rng), g(rng)};
  return (1.0 / norm(v)) * v;
}

// ---- a head-on impact -----------------------------------------------------------------------

// The restitution and the duration of the overlap of two spheres meeting head on along a random
// axis, against the law's closed forms (closed_forms.hpp; for Hertz the duration's is the elastic
// one), with velocity Verlet and with Gear. 1%: the touch and the parting fall between steps
// (200 a collision; found by linear interpolation), and velocity Verlet's velocity lags the
// damping force by O(dt^2).
struct Impact3 {
  double rebound = 0.0;  ///< relative normal speed after, over that before
  double duration = 0.0; ///< s, of the overlap
  double closed_form = 0.0;
  double across = 0.0; ///< speed across the axis and spin times radius after, m/s
};

Impact3 head_on(NormalLaw law, Integrator integrator, double restitution) {
  std::mt19937 rng(5);
  const Vec3 axis = unit_at_random(rng);
  const double r = 1e-3, v = 0.2;
  Material m = testing::elastic_material();
  m.restitution = restitution;
  Scene3 scene;
  scene.materials = {m};
  const double start = 2.0 * r * 1.02;
  scene.add_sphere({.position = 0.5 * start * axis, .radius = r, .velocity = -0.5 * v * axis});
  scene.add_sphere({.position = -0.5 * start * axis, .radius = r, .velocity = 0.5 * v * axis});
  const double m_eff = 0.5 * scene.spheres.mass[0];
  const PairParameters p = mix(m, m, v);
  Impact3 out;
  out.closed_form =
      with_normal_law(law, [&]<class N>() { return N::collision_time(p, m_eff, 0.5 * r, v); });
  Settings3 settings{.timestep = out.closed_form / 200.0,
                     .integrator = integrator,
                     .normal_law = law,
                     .impact_speed = v};
  Simulation3 s(std::move(scene), settings);
  const Spheres& sp = s.scene().spheres;
  const auto overlap = [&] { return 2.0 * r - norm(sp.position[0] - sp.position[1]); };
  double before = overlap(), touch = -1.0, part = -1.0;
  for (int k = 0; k < 100000 && part < 0.0; ++k) {
    s.step();
    const double now = overlap(), t = s.time(), dt = settings.timestep;
    if (before <= 0.0 && now > 0.0) touch = t - dt * now / (now - before);
    if (before > 0.0 && now <= 0.0) part = t - dt * now / (now - before);
    before = now;
  }
  EXPECT_GT(part, 0.0) << "the spheres never parted";
  out.rebound = dot(sp.velocity[0] - sp.velocity[1], axis) / v;
  out.duration = part - touch;
  out.across =
      norm(sp.velocity[0] - dot(sp.velocity[0], axis) * axis) + norm(sp.angular_velocity[0]) * r;
  return out;
}

class HeadOn3 : public ::testing::TestWithParam<std::tuple<NormalLaw, Integrator>> {};

TEST_P(HeadOn3, AnElasticImpactLastsTheClosedFormsTime) {
  const auto [law, integrator] = GetParam();
  const Impact3 c = head_on(law, integrator, 1.0);
  EXPECT_NEAR(c.rebound, 1.0, 0.01);
  EXPECT_NEAR(c.duration, c.closed_form, 0.01 * c.closed_form);
  EXPECT_LT(c.across, 1e-12); // head on: nothing across the axis, no spin
}

TEST_P(HeadOn3, ReboundsWithTheRestitutionItWasGiven) {
  const auto [law, integrator] = GetParam();
  const Impact3 c = head_on(law, integrator, 0.8);
  EXPECT_NEAR(c.rebound, 0.8, 0.01 * 0.8);
  if (law == law_id<LinearSpringDashpot>) { // the damped closed form is the linear law's
    EXPECT_NEAR(c.duration, c.closed_form, 0.01 * c.closed_form);
  }
  EXPECT_LT(c.across, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(
    Laws, HeadOn3,
    ::testing::Combine(::testing::Values(law_id<LinearSpringDashpot>, law_id<HertzViscoelastic>),
                       ::testing::Values(Integrator::verlet, Integrator::gear)),
    [](const auto& param_info) {
      return std::string(name_of(std::get<0>(param_info.param))) + "_" +
             std::string(to_string(std::get<1>(param_info.param)));
    });

// ---- a sphere sliding on a floor ------------------------------------------------------------

class Rolling3 : public ::testing::TestWithParam<TangentialLaw> {};

// A sphere slid along a random direction of a floor starts to roll at 5/7 v0 after
// 2 v0 / (7 mu g), with its spin about the horizontal axis across its path (tolerance:
// reference::rolling_tolerance, as the 2D test's).
TEST_P(Rolling3, StartsToRollAtTheClassicalSpeedAndTime) {
  const double r = 5.0e-3, v0 = 0.5, mu = 0.3, g = 9.81, heading = 0.7;
  Material m = testing::elastic_material(1.0e6);
  m.restitution = 0.3;
  m.friction = mu;
  m.tangential_damping = 2000.0;
  Scene3 scene;
  scene.materials = {m};
  scene.gravity = {0.0, 0.0, -g};
  scene.plates.push_back(make_plane({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}));
  const double mass = shape_mass(Shape::sphere, r, m.density);
  const Vec3 along{std::cos(heading), std::sin(heading), 0.0};
  scene.add_sphere({.position = {0.0, 0.0, r - mass * g / m.normal_stiffness},
                    .radius = r,
                    .velocity = v0 * along});
  Settings3 settings{.timestep = linear_collision_time(m.normal_stiffness, 0.0, mass) / 50.0,
                     .tangential_law = GetParam()};
  Simulation3 s(std::move(scene), settings);
  const double t_ref = reference::sphere_roll_time_factor * v0 / (mu * g);
  const double v_ref = reference::sphere_roll_speed_ratio * v0;
  const Spheres& sp = s.scene().spheres;
  const auto slip = [&] {
    return sp.velocity[0] + cross(sp.angular_velocity[0], Vec3{0.0, 0.0, -r});
  };
  double t_roll = -1.0, v_roll = 0.0;
  while (s.time() < 2.0 * t_ref) {
    s.step();
    if (norm(slip()) < 0.01 * v0) {
      t_roll = s.time();
      v_roll = dot(sp.velocity[0], along);
      break;
    }
  }
  ASSERT_GT(t_roll, 0.0) << "never started to roll";
  EXPECT_NEAR(t_roll, t_ref, t_ref * reference::rolling_tolerance);
  EXPECT_NEAR(v_roll, v_ref, v_ref * reference::rolling_tolerance);
  s.run(2000);
  EXPECT_NEAR(dot(sp.velocity[0], along), v_ref, v_ref * reference::rolling_tolerance);
  // it rolls straight on: its spin about the floor's axis across its heading
  const Vec3 across = cross(Vec3{0.0, 0.0, 1.0}, along);
  EXPECT_NEAR(dot(sp.angular_velocity[0], across) * r, v_ref, v_ref * reference::rolling_tolerance);
  EXPECT_LT(std::abs(dot(sp.angular_velocity[0], along)) * r, 1e-9 * v0);
}

INSTANTIATE_TEST_SUITE_P(Laws, Rolling3,
                         ::testing::Values(law_id<CundallStrack>, law_id<ViscousCoulomb>),
                         [](const auto& param_info) {
                           return std::string(name_of(param_info.param));
                         });

// ---- counter-spinning spheres ---------------------------------------------------------------

// Two equal spheres meet head on along x, both spinning fast about z: their surfaces slide past
// each other at the contact all through it (gross sliding), so the tangential force is mu F_n at
// every step. Summed over the steps (the impulses velocity Verlet gives), the tangential impulse
// is mu times the normal one, and each spin slows by R times the tangential impulse over I
// (lever arms at the radius), to rounding; the two spheres' changes are equal and opposite, and
// nothing moves along z. (The line of centres turns a little as they slide, so the impulses are
// summed along each step's own normal, not along x.)
TEST(CounterSpinning3, SlidingThroughoutTradesMuTimesTheNormalImpulse) {
  const double r = 1e-3, v = 0.1, spin = 600.0, mu = 0.3;
  Material m = testing::elastic_material();
  m.restitution = 0.8;
  m.friction = mu;
  m.tangential_damping = 1e6; // 1/s: the viscous law at its Coulomb cap from the first step
  Scene3 scene;
  scene.materials = {m};
  const double start = r * 1.01;
  scene.add_sphere({.position = {-start, 0.0, 0.0},
                    .radius = r,
                    .velocity = {v, 0.0, 0.0},
                    .angular_velocity = {0.0, 0.0, spin}});
  scene.add_sphere({.position = {start, 0.0, 0.0},
                    .radius = r,
                    .velocity = {-v, 0.0, 0.0},
                    .angular_velocity = {0.0, 0.0, spin}});
  const double mass = scene.spheres.mass[0], inertia = scene.spheres.inertia[0];
  Settings3 settings{.timestep = linear_collision_time(m.normal_stiffness, 0.0, 0.5 * mass) / 100.0,
                     .tangential_law = law_id<ViscousCoulomb>,
                     .lever_arm = LeverArm::radius};
  Simulation3 s(std::move(scene), settings);
  const Spheres& p = s.scene().spheres;
  double normal = 0.0, tangential = 0.0; // impulses on sphere 0, N s
  for (int k = 0; k < 3000; ++k) {
    s.step();
    const Vec3 n = (1.0 / norm(p.position[0] - p.position[1])) * (p.position[0] - p.position[1]);
    const Vec3 f = p.force[0];
    normal += dot(f, n) * settings.timestep;
    tangential += norm(f - dot(f, n) * n) * settings.timestep;
  }
  ASSERT_GT(norm(p.position[1] - p.position[0]), 2.0 * r) << "still touching";
  ASSERT_LT(p.velocity[0].x, 0.0); // it rebounded
  EXPECT_NEAR(tangential, mu * normal, 1e-12 * normal);
  const double slowed = r * tangential / inertia;
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(p.angular_velocity[i].z, spin - slowed, 1e-9 * spin);
    EXPECT_EQ(p.velocity[i].z, 0.0);
    EXPECT_EQ(p.angular_velocity[i].x, 0.0);
    EXPECT_EQ(p.angular_velocity[i].y, 0.0);
  }
  EXPECT_NEAR(p.velocity[0].y, -p.velocity[1].y, 1e-15);
  EXPECT_GT(std::abs(p.velocity[0].y), 0.1 * mu * v); // the friction pushed them apart sideways
  EXPECT_GT(slowed, 0.1 * spin);                      // and slowed the spins
  EXPECT_NEAR(normal, mass * (v - p.velocity[0].x), 1e-2 * normal); // the normal impulse
}

} // namespace
} // namespace talus
