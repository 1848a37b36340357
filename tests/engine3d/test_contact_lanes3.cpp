// Two contacts of spheres side by side (engine3d/pair_lanes3.hpp: the 3D force pass computes its
// pair contacts so) give, lane by lane, exactly the bits of one contact through the 3D
// pair_geometry and contact_force, for every law pair: the plate contacts, the energy and the
// LAMMPS package take the scalar form, and the engines agree to rounding only if both forms
// agree to the last bit. Tolerance: none (bit patterns are compared).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "engine3d/pair_lanes3.hpp"
#include "support/lane_parameter_sets.hpp"
#include "talus/law_table.hpp"

namespace talus {
namespace {

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

// One random contact of spheres: what the force pass knows of it before the law runs.
struct Sample3 {
  Vec3 d, v_i, v_j, w_i, w_j, spring;
  double r_i, r_j, m_i, m_j;
  int pair; // which parameter set
};

Vec3 random_vector(std::mt19937_64& rng, double size) {
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  return {size * u(rng), size * u(rng), size * u(rng)};
}

Sample3 draw(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Sample3 s;
  s.r_i = 1e-3 + 4e-3 * u(rng);
  s.r_j = 1e-3 + 4e-3 * u(rng);
  Vec3 axis = random_vector(rng, 1.0);
  axis = (1.0 / norm(axis)) * axis;
  const double dist = (s.r_i + s.r_j) * (1.0 - 0.05 * u(rng)); // overlaps up to 5%
  s.d = dist * axis;
  s.m_i = 1e-4 + 1e-2 * u(rng);
  s.m_j = 1e-4 + 1e-2 * u(rng);
  // a tenth at rest (v_t = 0 exactly), the others from 1 mm/s to 30 m/s
  const double speed = u(rng) < 0.1 ? 0.0 : std::pow(10.0, -3.0 + 4.5 * u(rng));
  s.v_i = random_vector(rng, speed), s.v_j = random_vector(rng, speed);
  s.w_i = random_vector(rng, 100.0 * speed), s.w_j = random_vector(rng, 100.0 * speed);
  // springs from none (a new contact) through sticking to far beyond the Coulomb limit, most
  // out of the tangent plane, as a turned contact's are
  s.spring = u(rng) < 0.1 ? Vec3{} : random_vector(rng, 1e-4);
  s.pair = static_cast<int>(u(rng) * 3.0);
  return s;
}

void expect_same_bits(const Vec3& lane, const Vec3& one) {
  EXPECT_EQ(bits(lane.x), bits(one.x));
  EXPECT_EQ(bits(lane.y), bits(one.y));
  EXPECT_EQ(bits(lane.z), bits(one.z));
}

template <class N, class T> void expect_lanes_match_scalar(const std::string& laws) {
  const std::vector<PairParameters> params = testing::lane_parameter_sets();
  std::mt19937_64 rng(11);
  const double dt = 1e-5;
  const bool with_r_eff = N::uses_r_eff || T::uses_r_eff;
  int compared = 0, released = 0, slipping = 0;
  for (int k = 0; k < 3000; ++k) {
    const Sample3 s[2] = {draw(rng), draw(rng)};
    const auto lanes = [&](auto field) { return Lanes{field(s[0]), field(s[1])}; };
    const auto vectors = [&](auto field) {
      return vec3_lanes_from<Lanes>([&](int lane) { return field(s[lane]); });
    };
    const Vec3Of<Lanes> d = vectors([](const Sample3& c) { return c.d; });
    const ContactGeometry3Of<Lanes> g =
        pair_geometry(d, square_root(dot(d, d)), lanes([](const Sample3& c) { return c.r_i; }),
                      lanes([](const Sample3& c) { return c.r_j; }),
                      lanes([](const Sample3& c) { return c.m_i; }),
                      lanes([](const Sample3& c) { return c.m_j; }),
                      vectors([](const Sample3& c) { return c.v_i; }),
                      vectors([](const Sample3& c) { return c.v_j; }),
                      vectors([](const Sample3& c) { return c.w_i; }),
                      vectors([](const Sample3& c) { return c.w_j; }), with_r_eff);
    Vec3Of<Lanes> spring = vectors([](const Sample3& c) { return c.spring; });
    const PairParametersOf<Lanes> p = PairParametersOf<Lanes>::gather(
        params[static_cast<std::size_t>(s[0].pair)], params[static_cast<std::size_t>(s[1].pair)],
        [](double x, double y) {
          return Lanes{x, y};
        });
    const ContactForce3Of<Lanes> f = contact_force<N, T>(p, g, spring, dt);
    for (int lane = 0; lane < 2; ++lane) {
      const Sample3& c = s[lane];
      const ContactGeometry3 one = pair_geometry(c.d, norm(c.d), c.r_i, c.r_j, c.m_i, c.m_j, c.v_i,
                                                 c.v_j, c.w_i, c.w_j, with_r_eff);
      Vec3 history = c.spring;
      const PairParameters& q = params[static_cast<std::size_t>(c.pair)];
      const ContactForce3 expected = contact_force<N, T>(q, one, history, dt);
      SCOPED_TRACE(laws + ", sample " + std::to_string(k) + ", lane " + std::to_string(lane));
      expect_same_bits(lane_of(f.force, lane), expected.force);
      expect_same_bits(lane_of(f.torque_i, lane), expected.torque_i);
      expect_same_bits(lane_of(f.torque_j, lane), expected.torque_j);
      expect_same_bits(lane_of(spring, lane), history);
      const ContactGeometry3 back = lane_of(g, lane);
      EXPECT_EQ(bits(back.overlap), bits(one.overlap));
      expect_same_bits(back.v_tangent, one.v_tangent);
      if (::testing::Test::HasFailure()) return;
      ++compared;
      released += expected.normal_force == 0.0;
      const Vec3 ft = expected.force - expected.normal_force * one.normal;
      slipping +=
          expected.normal_force > 0.0 &&
          std::abs(norm(ft) - q.friction * expected.normal_force) < 1e-12 * expected.normal_force;
    }
  }
  EXPECT_EQ(compared, 6000);
  // the samples reach the branches the selects replace: separating contacts whose normal force
  // is cut at zero and, with friction, contacts at the Coulomb limit
  EXPECT_GT(released, 100) << laws;
  if constexpr (!std::is_same_v<T, Frictionless>) {
    EXPECT_GT(slipping, 100) << laws;
  }
}

// every pair of laws in the table (talus/law_table.hpp)
TEST(ContactLanes3, EveryLawPairGivesTheScalarBits) {
  for (std::size_t n = 0; n < NormalLaws::size; ++n)
    for (std::size_t t = 0; t < TangentialLaws::size; ++t) {
      const NormalLaw normal{static_cast<std::uint8_t>(n)};
      const TangentialLaw tangential{static_cast<std::uint8_t>(t)};
      with_contact_law(normal, tangential, [&]<class N, class T>() {
        expect_lanes_match_scalar<N, T>(std::string(name_of(normal)) + ", " +
                                        std::string(name_of(tangential)));
      });
    }
}

} // namespace
} // namespace talus
