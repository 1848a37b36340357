// The contact laws for spheres in 3D (contact_geometry_3d.hpp, contact_force.hpp): the same law
// lines as in 2D on vectors. Checked against the 2D contact in a plane, against a rotation of
// the whole contact, and against the closed form of a sliding oblique impact with spin about
// any axis. Tolerances are rounding's: the 3D lines take other products and sums than the 2D
// ones (the tangential velocity as dv - (dv.n) n rather than dv.t, a spring turned into the
// plane by a rescaling), a few ulp of each quantity per step.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "talus/law_table.hpp"
#include "talus/rolling_resistance.hpp"

namespace talus {
namespace {

// tangential_damping: the viscous Coulomb law's rate (1/s), and the spring laws' dashpot's
PairParameters params(double friction = 0.5, double tangential_damping = 200.0) {
  Material m;
  m.young = 1e8;
  m.poisson = 0.3;
  m.normal_stiffness = 1e4;
  m.friction = friction;
  m.tangential_damping = tangential_damping;
  return mix(m, m, 1.0);
}

// Two grains of radius ~1 mm in a plane, touching, moving and spinning at random: the state a
// 2D engine and a 3D one (z = 0, spins along z) both see.
struct PlanarPair {
  double x_i, y_i, x_j, y_j, r_i, r_j, m_i, m_j, vx_i, vy_i, vx_j, vy_j, w_i, w_j;
};

PlanarPair random_pair(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PlanarPair s{};
  s.r_i = 1e-3 * (1.0 + 0.2 * u(rng));
  s.r_j = 1e-3 * (1.0 + 0.2 * u(rng));
  const double angle = 3.14159 * u(rng), dist = (s.r_i + s.r_j) * (1.0 - 2e-3);
  s.x_j = 0.0, s.y_j = 0.0;
  s.x_i = dist * std::cos(angle), s.y_i = dist * std::sin(angle);
  s.m_i = 1e-5 * (1.0 + 0.3 * u(rng));
  s.m_j = 1e-5 * (1.0 + 0.3 * u(rng));
  s.vx_i = 0.05 * u(rng), s.vy_i = 0.05 * u(rng), s.vx_j = 0.05 * u(rng), s.vy_j = 0.05 * u(rng);
  s.w_i = 50.0 * u(rng), s.w_j = 50.0 * u(rng);
  return s;
}

ContactGeometry geometry_2d(const PlanarPair& s) {
  const double dx = s.x_i - s.x_j, dy = s.y_i - s.y_j;
  return pair_geometry(dx, dy, std::hypot(dx, dy), s.r_i, s.r_j, s.m_i, s.m_j, s.vx_i, s.vy_i,
                       s.vx_j, s.vy_j, s.w_i, s.w_j);
}

ContactGeometry3 geometry_3d(const PlanarPair& s) {
  const Vec3 d{s.x_i - s.x_j, s.y_i - s.y_j, 0.0};
  return pair_geometry(d, std::hypot(d.x, d.y), s.r_i, s.r_j, s.m_i, s.m_j,
                       Vec3{s.vx_i, s.vy_i, 0.0}, Vec3{s.vx_j, s.vy_j, 0.0}, Vec3{0.0, 0.0, s.w_i},
                       Vec3{0.0, 0.0, s.w_j});
}

// A 3D contact whose motion lies in the x-y plane is the 2D contact: every law pair, over 400
// steps of the pair's own motion (the contact turns, its spring is carried round), to 1e-12 of
// the force and of the spring's largest stretch (a few ulp: the 3D lines round differently).
TEST(Contact3D, APlanarContactIsThe2DContact) {
  const PairParameters p = params();
  std::mt19937 rng(7);
  const double dt = 1e-6;
  for (int n = 0; n < 2; ++n)
    for (int t = 0; t < 4; ++t)
      with_contact_law(NormalLaw{static_cast<std::uint8_t>(n)},
                       TangentialLaw{static_cast<std::uint8_t>(t)}, [&]<class N, class T>() {
                         for (int sample = 0; sample < 20; ++sample) {
                           PlanarPair s = random_pair(rng);
                           double spring_2d = 0.0, largest = 0.0;
                           Vec3 spring_3d{};
                           for (int step = 0; step < 400; ++step) {
                             const ContactGeometry g2 = geometry_2d(s);
                             if (g2.overlap <= 0.0) break;
                             const ContactForce f2 = contact_force<N, T>(p, g2, spring_2d, dt);
                             const ContactForce3 f3 =
                                 contact_force<N, T>(p, geometry_3d(s), spring_3d, dt);
                             const double scale = std::hypot(f2.force_x, f2.force_y);
                             ASSERT_NEAR(f3.force.x, f2.force_x, 1e-12 * scale)
                                 << N::name << T::name;
                             ASSERT_NEAR(f3.force.y, f2.force_y, 1e-12 * scale);
                             ASSERT_EQ(f3.force.z, 0.0);
                             ASSERT_NEAR(f3.torque_i.z, f2.torque_i, 1e-12 * scale * 1e-3);
                             ASSERT_NEAR(f3.torque_j.z, f2.torque_j, 1e-12 * scale * 1e-3);
                             ASSERT_EQ(f3.torque_i.x, 0.0);
                             // the spring: 2D's scalar along t = e_z x n is 3D's vector
                             const Vec3 along{-g2.normal_y, g2.normal_x, 0.0};
                             largest = std::max(largest, std::abs(spring_2d));
                             ASSERT_NEAR(dot(spring_3d, along), spring_2d, 1e-12 * largest);
                             // the pair moves on: the contact turns
                             s.x_i += s.vx_i * dt * 20.0, s.y_i += s.vy_i * dt * 20.0;
                             s.x_j += s.vx_j * dt * 20.0, s.y_j += s.vy_j * dt * 20.0;
                           }
                         }
                       });
}

Vec3 rotated(const Eigen::Matrix3d& q, const Vec3& v) {
  const Eigen::Vector3d r = q * Eigen::Vector3d(v.x, v.y, v.z);
  return {r.x(), r.y(), r.z()};
}

double distance(const Vec3& a, const Vec3& b) {
  return magnitude(a - b);
}

// Isotropy: a 3D contact (velocities and spins along every axis), and the same contact turned by
// a random rotation Q, give forces, torques and springs that are Q times each other, to rounding
// over 300 steps in which the springs load, turn and slip: 1e-10 of the largest force and
// spring of the contact (its elastic and viscous parts, each rounded in its own frame, cancel as
// the grains part).
TEST(Contact3D, ARotatedContactGivesTheRotatedForce) {
  const PairParameters p = params();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double dt = 1e-6, r = 1e-3, m = 1e-5;
  for (int t = 0; t < 4; ++t)
    with_contact_law(
        NormalLaw{1}, TangentialLaw{static_cast<std::uint8_t>(t)}, [&]<class N, class T>() {
          for (int sample = 0; sample < 10; ++sample) {
            const Eigen::Matrix3d q =
                Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
            Vec3 d{u(rng), u(rng), u(rng)};
            d = ((2.0 * r - 2e-6) / magnitude(d)) * d;
            const Vec3 v{0.05 * u(rng), 0.05 * u(rng), 0.05 * u(rng)};
            const Vec3 w_i{50.0 * u(rng), 50.0 * u(rng), 50.0 * u(rng)};
            const Vec3 w_j{50.0 * u(rng), 50.0 * u(rng), 50.0 * u(rng)};
            Vec3 spring{}, spring_q{};
            double scale = 0.0, stretch = 0.0; // the largest force and spring
            for (int step = 0; step < 300; ++step) {
              const Vec3 dq = rotated(q, d);
              const ContactGeometry3 g =
                  pair_geometry(d, magnitude(d), r, r, m, m, v, Vec3{}, w_i, w_j);
              const ContactGeometry3 gq =
                  pair_geometry(dq, magnitude(dq), r, r, m, m, rotated(q, v), Vec3{},
                                rotated(q, w_i), rotated(q, w_j));
              if (g.overlap <= 0.0) break;
              const ContactForce3 f = contact_force<N, T>(p, g, spring, dt);
              const ContactForce3 fq = contact_force<N, T>(p, gq, spring_q, dt);
              scale = std::max(scale, magnitude(f.force));
              stretch = std::max(stretch, magnitude(spring));
              ASSERT_LT(distance(rotated(q, f.force), fq.force), 1e-10 * scale)
                  << T::name << " step " << step;
              ASSERT_LT(distance(rotated(q, f.torque_i), fq.torque_i), 1e-10 * scale * r);
              ASSERT_LT(distance(rotated(q, spring), spring_q), 1e-10 * stretch + 1e-30);
              d = d + (20.0 * dt) * v;
            }
          }
        });
}

// The spring turned into the tangent plane keeps its length and lies in the plane; a slipping
// spring law's force in 3D is mu F_n against the slip, in any direction of the tangent plane.
TEST(Contact3D, TheSpringTurnsWithTheContactAndSlipsAgainstTheSlip) {
  const Vec3 n = Vec3{0.3, -0.4, 0.866} / magnitude(Vec3{0.3, -0.4, 0.866});
  const Vec3 h{1e-6, 2e-6, -0.5e-6};
  const Vec3 turned = into_tangent_plane(h, n);
  EXPECT_NEAR(dot(turned, n), 0.0, 1e-15 * magnitude(h));
  EXPECT_NEAR(magnitude(turned), magnitude(h), 1e-21);

  const PairParameters p = params(0.4, 1e6); // the viscous Coulomb law's part never binds
  const double r = 1e-3, m = 1e-5;
  const Vec3 d = (2.0 * r - 2e-5) * n;
  // a slip along a tangent direction at 45 degrees between two axes of the plane
  const Vec3 e1 = cross(n, Vec3{1.0, 0.0, 0.0}) / magnitude(cross(n, Vec3{1.0, 0.0, 0.0}));
  const Vec3 e2 = cross(n, e1);
  const Vec3 slip = 0.1 * ((1.0 / std::sqrt(2.0)) * (e1 + e2));
  const ContactGeometry3 g =
      pair_geometry(d, magnitude(d), r, r, m, m, slip, Vec3{}, Vec3{}, Vec3{});
  for (int t = 0; t < 3; ++t) // the laws with friction
    with_contact_law(
        NormalLaw{0}, TangentialLaw{static_cast<std::uint8_t>(t)}, [&]<class N, class T>() {
          Vec3 spring{};
          ContactForce3 f{};
          for (int step = 0; step < 2000; ++step) f = contact_force<N, T>(p, g, spring, 1e-6);
          const Vec3 ft = f.force - f.normal_force * n;
          EXPECT_NEAR(magnitude(ft), 0.4 * f.normal_force, 1e-12 * f.normal_force) << T::name;
          EXPECT_NEAR(dot(ft, slip) / magnitude(slip), -magnitude(ft), 1e-12 * f.normal_force);
        });
}

// A sphere thrown obliquely at a plane, spinning about an axis out of every plane of symmetry,
// sliding throughout the contact: its tangential impulse is mu times its normal impulse and
// opposes the slip, whose direction stays fixed (Maw, Barber & Fawcett 1976's gross sliding in
// 3D). Lever arms at the radius, as the 2D sliding test's (docs/validation.md): with the arm at
// the contact point R - xi/2, which moves as xi does, the spin's share of the slip turns a
// little (5e-5 rad here) and the direction is only nearly fixed. Integrated here with symplectic
// Euler, the Coulomb law's viscous part never binding (eta_t |v_t| >> mu F_n); bound 1e-12
// relative, rounding over a thousand steps.
TEST(Contact3D, ASlidingObliqueImpactWithSpinAboutAnyAxis) {
  const PairParameters p = params(0.3, 1e6);
  const double r = 1e-3, m = 1e-5, inertia = 0.4 * m * r * r, dt = 1e-7;
  const Vec3 n{0.0, 0.0, 1.0};
  Vec3 x{0.0, 0.0, r}, v{0.3, -0.2, -0.1}, w{40.0, 25.0, -60.0};
  Vec3 impulse{}, spring{};
  Vec3 first_slip{};
  for (int step = 0; step < 200000; ++step) {
    const Vec3 d{0.0, 0.0, x.z};
    const ContactGeometry3 g =
        wall_geometry(d, x.z, r, m, v, w, Vec3{}, lever_shares(LeverArm::radius));
    Vec3 force{}, torque{};
    if (g.overlap > 0.0) {
      if (magnitude(first_slip) == 0.0) first_slip = g.v_tangent;
      ASSERT_GT(dot(g.v_tangent, first_slip), 0.0) << "the contact stopped sliding";
      const ContactForce3 f = contact_force<LinearSpringDashpot, ViscousCoulomb>(p, g, spring, dt);
      force = f.force;
      torque = f.torque_i;
      impulse += dt * force;
    } else if (step > 0 && v.z > 0.0) {
      break;
    }
    v += (dt / m) * force;
    w += (dt / inertia) * torque;
    x += dt * v;
  }
  const Vec3 tangential = impulse - dot(impulse, n) * n;
  EXPECT_NEAR(magnitude(tangential), 0.3 * dot(impulse, n), 1e-12 * dot(impulse, n));
  // against the first slip, in its direction
  EXPECT_NEAR(dot(tangential, first_slip) / magnitude(first_slip), -magnitude(tangential),
              1e-12 * dot(impulse, n));
}

// Rolling resistance on vectors: a planar pair's rolling torque is the 2D one.
TEST(Contact3D, RollingResistanceInAPlaneIsThe2DOne) {
  Material mat;
  mat.young = 1e8;
  mat.poisson = 0.3;
  mat.normal_stiffness = 1e4;
  mat.friction = 0.5;
  mat.rolling_friction = 0.1;
  const PairParameters p = mix(mat, mat, 1.0);
  std::mt19937 rng(3);
  for (int sample = 0; sample < 20; ++sample) {
    const PlanarPair s = random_pair(rng);
    const ContactGeometry g2 = geometry_2d(s);
    const ContactGeometry3 g3 = geometry_3d(s);
    double theta_2d = 0.0;
    Vec3 theta_3d{};
    for (int step = 0; step < 300; ++step) {
      const double fn = LinearSpringDashpot::force(p, g2);
      const double m2 =
          RollingLaw::torque<LinearSpringDashpot>(p, g2, fn, s.w_i - s.w_j, 1e-11, theta_2d, 1e-6);
      theta_3d = into_tangent_plane(theta_3d, g3.normal);
      const Vec3 spin = rolling_spin(Vec3{0, 0, s.w_i}, Vec3{0, 0, s.w_j}, g3.normal);
      const Vec3 m3 =
          RollingLaw::torque<LinearSpringDashpot>(p, g3, fn, spin, 1e-11, theta_3d, 1e-6);
      ASSERT_NEAR(m3.z, m2, 1e-12 * std::abs(m2) + 1e-30);
      ASSERT_EQ(m3.x, 0.0);
    }
  }
}

// A contact whose normal force is cut to zero (a dashpot as the spheres part) with no spin and
// no rolling spring: the moment's limit is zero and the spring's direction undefined; the torque
// and the spring stay zero, not NaN (as a sphere landing on another without spin meets).
TEST(Contact3D, RollingResistanceWithoutLoadOrSpinIsZero) {
  Material mat;
  mat.rolling_friction = 0.1;
  const PairParameters p = mix(mat, mat, 1.0);
  ContactGeometry3 g;
  g.normal = {1.0, 0.0, 0.0};
  g.overlap = 1e-6, g.r_eff = 1e-3, g.m_eff = 1e-4;
  Vec3 theta{};
  const Vec3 m = RollingLaw::torque<LinearSpringDashpot>(p, g, 0.0, Vec3{}, 1e-11, theta, 1e-6);
  EXPECT_EQ(m.x, 0.0);
  EXPECT_EQ(m.y, 0.0);
  EXPECT_EQ(m.z, 0.0);
  EXPECT_EQ(magnitude(theta), 0.0);
}

} // namespace
} // namespace talus
