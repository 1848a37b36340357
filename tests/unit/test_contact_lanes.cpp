// Two contacts side by side (core/contact_lanes.hpp) give, lane by lane, exactly the bits of
// one contact through pair_geometry and contact_force, for every law pair: the force stage uses
// the lanes, the wall contacts and the observers the scalar form, and runs stay reproducible
// only if both agree to the last bit. Tolerance: none (bit patterns are compared).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <type_traits>

#include "core/contact_lanes.hpp"
#include "core/contact_vectors.hpp"
#include "support/lane_parameter_sets.hpp"
#include "talus/law_table.hpp"

namespace talus {
namespace {

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

// One random contact: what the force stage knows of it before the law runs.
struct Sample {
  Vec2 d, v_i, v_j;
  double r_i, r_j, m_i, m_j, w_i, w_j, history;
  int pair; // which parameter set
};

Sample draw(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Sample s;
  s.r_i = 1e-3 + 4e-3 * u(rng);
  s.r_j = 1e-3 + 4e-3 * u(rng);
  const double angle = 6.283185307179586 * u(rng);
  const double dist = (s.r_i + s.r_j) * (1.0 - 0.05 * u(rng)); // overlaps up to 5%
  s.d = {dist * std::cos(angle), dist * std::sin(angle)};
  s.m_i = 1e-4 + 1e-2 * u(rng);
  s.m_j = 1e-4 + 1e-2 * u(rng);
  // a tenth at rest (v_t = 0 exactly), the others from 1 mm/s to 30 m/s
  const double speed = u(rng) < 0.1 ? 0.0 : std::pow(10.0, -3.0 + 4.5 * u(rng));
  s.v_i = {speed * (u(rng) - 0.5), speed * (u(rng) - 0.5)};
  s.v_j = {speed * (u(rng) - 0.5), speed * (u(rng) - 0.5)};
  s.w_i = speed * 100.0 * (u(rng) - 0.5);
  s.w_j = speed * 100.0 * (u(rng) - 0.5);
  s.history = 1e-4 * (u(rng) - 0.5); // springs from sticking to far beyond the Coulomb limit
  s.pair = static_cast<int>(u(rng) * 3.0);
  return s;
}

// `with_friction`: the law reaches the Coulomb limit (not so for the frictionless law)
template <class N, class T> void expect_lanes_match_scalar(const char* laws, bool with_friction) {
  const std::vector<PairParameters> params = testing::lane_parameter_sets();
  std::mt19937_64 rng(7);
  const double dt = 1e-5;
  int compared = 0, slipping = 0, released = 0;
  for (int k = 0; k < 4000; ++k) {
    const Sample s[2] = {draw(rng), draw(rng)};
    const auto lanes = [&](auto field) { return Lanes{field(s[0]), field(s[1])}; };
    const Lanes dx = lanes([](const Sample& c) { return c.d.x; });
    const Lanes dy = lanes([](const Sample& c) { return c.d.y; });
    const ContactLanes g = pair_geometry(
        dx, dy, square_root(dx * dx + dy * dy), lanes([](const Sample& c) { return c.r_i; }),
        lanes([](const Sample& c) { return c.r_j; }), lanes([](const Sample& c) { return c.m_i; }),
        lanes([](const Sample& c) { return c.m_j; }),
        lanes([](const Sample& c) { return c.v_i.x; }),
        lanes([](const Sample& c) { return c.v_i.y; }),
        lanes([](const Sample& c) { return c.v_j.x; }),
        lanes([](const Sample& c) { return c.v_j.y; }),
        lanes([](const Sample& c) { return c.w_i; }), lanes([](const Sample& c) { return c.w_j; }),
        N::uses_r_eff || T::uses_r_eff);
    Lanes spring = lanes([](const Sample& c) { return c.history; });
    const ForceLanes f =
        contact_force<N, T>(pair_lanes(params[static_cast<std::size_t>(s[0].pair)],
                                       params[static_cast<std::size_t>(s[1].pair)]),
                            g, spring, dt);
    for (int lane = 0; lane < 2; ++lane) {
      const Sample& c = s[lane];
      const ContactGeometry one =
          pair_geometry(c.d, std::sqrt(norm2(c.d)), c.r_i, c.r_j, c.m_i, c.m_j, c.v_i, c.v_j, c.w_i,
                        c.w_j, N::uses_r_eff || T::uses_r_eff);
      double history = c.history;
      const ContactForce expected =
          contact_force<N, T>(params[static_cast<std::size_t>(c.pair)], one, history, dt);
      SCOPED_TRACE(std::string(laws) + ", sample " + std::to_string(k) + ", lane " +
                   std::to_string(lane));
      ASSERT_EQ(bits(f.force_x[lane]), bits(expected.force_x));
      ASSERT_EQ(bits(f.force_y[lane]), bits(expected.force_y));
      ASSERT_EQ(bits(f.torque_i[lane]), bits(expected.torque_i));
      ASSERT_EQ(bits(f.torque_j[lane]), bits(expected.torque_j));
      ASSERT_EQ(bits(spring[lane]), bits(history));
      ++compared;
      released += expected.normal_force == 0.0;
      const double ft = dot(force_of(expected), tangent_of(one));
      slipping +=
          expected.normal_force > 0.0 &&
          std::abs(ft) == params[static_cast<std::size_t>(c.pair)].friction * expected.normal_force;
    }
  }
  EXPECT_EQ(compared, 8000);
  // the samples reach every branch the selects replace: separating contacts whose normal force
  // is cut at zero, and contacts at the Coulomb limit
  EXPECT_GT(released, 100) << laws;
  if (with_friction) {
    EXPECT_GT(slipping, 100) << laws;
  }
}

// every pair of laws in the table (talus/law_table.hpp)
TEST(ContactLanes, EveryLawPairGivesTheScalarBits) {
  for (std::size_t n = 0; n < NormalLaws::size; ++n)
    for (std::size_t t = 0; t < TangentialLaws::size; ++t) {
      const NormalLaw normal{static_cast<std::uint8_t>(n)};
      const TangentialLaw tangential{static_cast<std::uint8_t>(t)};
      const std::string laws =
          std::string(name_of(normal)) + ", " + std::string(name_of(tangential));
      with_contact_law(normal, tangential, [&]<class N, class T>() {
        expect_lanes_match_scalar<N, T>(laws.c_str(), !std::is_same_v<T, Frictionless>);
      });
    }
}

TEST(ContactLanes, HelpersFollowTheStandardFunctions) {
  const Lanes x{-0.0, 3.5}, y{2.0, -1.0};
  const Lanes m = magnitude(x), c = copy_sign(y, x), z = not_below_zero(Lanes{-1e-300, 0.0});
  EXPECT_EQ(bits(m[0]), bits(0.0));
  EXPECT_EQ(bits(c[0]), bits(std::copysign(2.0, -0.0)));
  EXPECT_EQ(bits(c[1]), bits(std::copysign(-1.0, 3.5)));
  EXPECT_EQ(bits(z[0]), bits(std::max(-1e-300, 0.0)));
  EXPECT_TRUE(std::isnan(not_below_zero(Lanes{std::nan(""), 1.0})[0])); // as std::max(NaN, 0)
  EXPECT_EQ(smaller(Lanes{1.0, 2.0}, Lanes{3.0, -4.0})[1], -4.0);
  EXPECT_EQ(square_root(Lanes{4.0, 2.0})[1], std::sqrt(2.0));
}

} // namespace
} // namespace talus
