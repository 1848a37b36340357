// Two contacts of spheres side by side (SSE2), and four (AVX2, in a build for it), as the 3D
// force pass computes its pair contacts (engine3d/pair_lanes3.hpp), give, lane by lane,
// exactly the bits of one contact through the 3D
// pair_geometry and contact_force, for every law pair: the plate contacts, the energy and the
// LAMMPS package take the scalar form, and the engines agree to rounding only if both forms
// agree to the last bit. Tolerance: none (bit patterns are compared).
#include <gtest/gtest.h>

#include <array>
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

// What the lanes computed, lane by lane.
struct LaneResults {
  Vec3 force[4], torque_i[4], torque_j[4], spring[4], v_tangent[4];
  double overlap[4];
};

// Contacts s[0, lanes of L) side by side, in lanes L.
template <class N, class T, class L>
[[gnu::always_inline]] inline void
in_lanes(const Sample3* s, const std::vector<PairParameters>& params, double dt, LaneResults& out) {
  const auto lanes = [&](auto field) { return lanes_from<L>([&](int k) { return field(s[k]); }); };
  const auto vectors = [&](auto field) {
    return vec3_lanes_from<L>([&](int k) { return field(s[k]); });
  };
  const Vec3Of<L> d = vectors([](const Sample3& c) { return c.d; });
  const ContactGeometry3Of<L> g = pair_geometry(
      d, square_root(dot(d, d)), lanes([](const Sample3& c) { return c.r_i; }),
      lanes([](const Sample3& c) { return c.r_j; }), lanes([](const Sample3& c) { return c.m_i; }),
      lanes([](const Sample3& c) { return c.m_j; }),
      vectors([](const Sample3& c) { return c.v_i; }),
      vectors([](const Sample3& c) { return c.v_j; }),
      vectors([](const Sample3& c) { return c.w_i; }),
      vectors([](const Sample3& c) { return c.w_j; }), N::uses_r_eff || T::uses_r_eff);
  Vec3Of<L> spring = vectors([](const Sample3& c) { return c.spring; });
  std::array<const PairParameters*, lane_count<L>> pair;
  for (int k = 0; k < lane_count<L>; ++k)
    pair[static_cast<std::size_t>(k)] = &params[static_cast<std::size_t>(s[k].pair)];
  const ContactForce3Of<L> f = contact_force<N, T>(parameters_in_lanes<L>(pair), g, spring, dt);
  for (int k = 0; k < lane_count<L>; ++k) {
    out.force[k] = lane_of(f.force, k), out.torque_i[k] = lane_of(f.torque_i, k);
    out.torque_j[k] = lane_of(f.torque_j, k), out.spring[k] = lane_of(spring, k);
    const ContactGeometry3 back = lane_of(g, k);
    out.overlap[k] = back.overlap, out.v_tangent[k] = back.v_tangent;
  }
}

template <class N, class T>
[[gnu::flatten]] void in_sse2_lanes(const Sample3* s, const std::vector<PairParameters>& params,
                                    double dt, LaneResults& out) {
  in_lanes<N, T, Lanes>(s, params, dt, out);
}
#if defined(__AVX2__)
template <class N, class T>
[[gnu::flatten]] void in_avx2_lanes(const Sample3* s, const std::vector<PairParameters>& params,
                                    double dt, LaneResults& out) {
  in_lanes<N, T, Lanes4>(s, params, dt, out);
}
#endif

template <class N, class T> void expect_lanes_match_scalar(const std::string& laws, int width) {
  const std::vector<PairParameters> params = testing::lane_parameter_sets();
  std::mt19937_64 rng(11);
  const double dt = 1e-5;
  const bool with_r_eff = N::uses_r_eff || T::uses_r_eff;
  int compared = 0, released = 0, slipping = 0;
  for (int k = 0; k < 6000 / width; ++k) {
    Sample3 s[4];
    for (int lane = 0; lane < width; ++lane) s[lane] = draw(rng);
    LaneResults f;
#if defined(__AVX2__)
    if (width == 4)
      in_avx2_lanes<N, T>(s, params, dt, f);
    else
#endif
      in_sse2_lanes<N, T>(s, params, dt, f);
    for (int lane = 0; lane < width; ++lane) {
      const Sample3& c = s[lane];
      const ContactGeometry3 one = pair_geometry(c.d, norm(c.d), c.r_i, c.r_j, c.m_i, c.m_j, c.v_i,
                                                 c.v_j, c.w_i, c.w_j, with_r_eff);
      Vec3 history = c.spring;
      const PairParameters& q = params[static_cast<std::size_t>(c.pair)];
      const ContactForce3 expected = contact_force<N, T>(q, one, history, dt);
      SCOPED_TRACE(laws + ", sample " + std::to_string(k) + ", lane " + std::to_string(lane) +
                   " of " + std::to_string(width));
      expect_same_bits(f.force[lane], expected.force);
      expect_same_bits(f.torque_i[lane], expected.torque_i);
      expect_same_bits(f.torque_j[lane], expected.torque_j);
      expect_same_bits(f.spring[lane], history);
      EXPECT_EQ(bits(f.overlap[lane]), bits(one.overlap));
      expect_same_bits(f.v_tangent[lane], one.v_tangent);
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
        const std::string laws =
            std::string(name_of(normal)) + ", " + std::string(name_of(tangential));
        expect_lanes_match_scalar<N, T>(laws, 2);
#if defined(__AVX2__) // the 3D engine built for AVX2 computes its contacts four at a time
        expect_lanes_match_scalar<N, T>(laws, 4);
#endif
      });
    }
}

} // namespace
} // namespace talus
