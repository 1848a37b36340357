// The 3D Verlet list against brute force: every pair within reach through every periodic image
// (the Lees-Edwards images too, offset along x across y), none more, and the springs of pairs
// still within reach carried over a rebuild.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>
#include <tuple>

#include "engine3d/sphere_list.hpp"
#include "talus/error.hpp"

namespace talus {
namespace {

constexpr double box = 12e-3; // m

Spheres random_spheres(std::size_t n, std::mt19937& rng) {
  std::uniform_real_distribution<double> at(0.0, box), size(0.8e-3, 1.2e-3);
  Spheres s;
  for (std::size_t i = 0; i < n; ++i)
    s.add({.position = {at(rng), at(rng), at(rng)},
           .radius = size(rng),
           .kind = i % 17 == 0 ? Kind::fixed : Kind::free,
           .mass = 1.0,
           .inertia = 1.0});
  return s;
}

using Entry = std::tuple<std::uint32_t, std::uint32_t, int, int, int>;

std::set<Entry> brute_force(const Spheres& s, const Domain3& d, double skin) {
  std::set<Entry> out;
  // across a Lees-Edwards side the images along x are an offset further: two widths each way
  const auto images = [&](int k) {
    if (!d.periodic[static_cast<std::size_t>(k)]) return 0;
    return k == 0 && d.shear_offset != 0.0 ? 2 : 1;
  };
  for (std::uint32_t i = 0; i < s.size(); ++i)
    for (std::uint32_t j = i + 1; j < s.size(); ++j) {
      if (!s.is_free(i) && !s.is_free(j)) continue;
      for (int sx = -images(0); sx <= images(0); ++sx)
        for (int sy = -images(1); sy <= images(1); ++sy)
          for (int sz = -images(2); sz <= images(2); ++sz) {
            const Vec3 image = s.position[j] + d.image_shift(sx, sy, sz);
            const double reach = s.radius[i] + s.radius[j] + skin;
            if (norm2(s.position[i] - image) < reach * reach) out.insert({i, j, sx, sy, sz});
          }
    }
  return out;
}

std::set<Entry> listed(const SphereList& list) {
  std::set<Entry> out;
  for (std::uint32_t i = 0; i + 1 < list.row_offset.size(); ++i)
    for (std::uint32_t e = list.row_offset[i]; e < list.row_offset[i + 1]; ++e)
      out.insert({i, list.neighbour[e], list.shift[e].x, list.shift[e].y, list.shift[e].z});
  return out;
}

class SphereListImages : public ::testing::TestWithParam<std::array<bool, 3>> {};

TEST_P(SphereListImages, HoldsEveryPairWithinReachAndNoOther) {
  std::mt19937 rng(7);
  Spheres s = random_spheres(400, rng);
  Domain3 d{.lo = {0.0, 0.0, 0.0}, .hi = {box, box, box}, .periodic = GetParam()};
  SphereList list;
  const double skin = 0.3e-3;
  build_sphere_list(list, s, {}, d, skin);
  const std::set<Entry> expected = brute_force(s, d, skin);
  EXPECT_GT(expected.size(), 400u);
  EXPECT_EQ(listed(list), expected);
  EXPECT_EQ(list.pair_count(), expected.size()); // no entry twice
}

INSTANTIATE_TEST_SUITE_P(Axes, SphereListImages,
                         ::testing::Values(std::array<bool, 3>{false, false, false},
                                           std::array<bool, 3>{true, false, false},
                                           std::array<bool, 3>{false, false, true},
                                           std::array<bool, 3>{true, true, true}));

// Offsets that put a row of cells across y anywhere between two columns of cells, or nearly a
// width along.
class SphereListLeesEdwards : public ::testing::TestWithParam<double> {};

TEST_P(SphereListLeesEdwards, HoldsEveryPairWithinReachThroughTheSlidingImages) {
  std::mt19937 rng(5);
  Spheres s = random_spheres(400, rng);
  Domain3 d{.lo = {0.0, 0.0, 0.0},
            .hi = {box, box, box},
            .periodic = {true, true, GetParam() > 0.5},
            .shear_offset = GetParam() * box};
  SphereList list;
  const double skin = 0.3e-3;
  build_sphere_list(list, s, {}, d, skin);
  const std::set<Entry> expected = brute_force(s, d, skin);
  std::size_t across = 0; // pairs through the sliding images
  for (const Entry& e : expected) across += std::get<3>(e) != 0 ? 1 : 0;
  EXPECT_GT(across, 20u);
  EXPECT_EQ(listed(list), expected);
  EXPECT_EQ(list.pair_count(), expected.size()); // no entry twice
}

INSTANTIATE_TEST_SUITE_P(Offsets, SphereListLeesEdwards,
                         ::testing::Values(0.013, 0.3, 0.5 + 1e-9, 0.77, 0.999));

TEST(SphereList, CarriesTheSpringsOfPairsStillWithinReach) {
  std::mt19937 rng(11);
  Spheres s = random_spheres(300, rng);
  Domain3 d{.lo = {0.0, 0.0, 0.0}, .hi = {box, box, box}, .periodic = {true, true, true}};
  SphereList list;
  build_sphere_list(list, s, {}, d, 0.4e-3);
  std::map<std::pair<std::uint32_t, std::uint32_t>, Vec3> set_to;
  for (std::uint32_t i = 0; i < s.size(); ++i)
    for (std::uint32_t e = list.row_offset[i]; e < list.row_offset[i + 1]; ++e) {
      list.spring[e] = {1.0 * e, -2.0 * i, 0.5};
      set_to[{i, list.neighbour[e]}] = list.spring[e];
    }
  // every sphere moves a little; some across a periodic side
  std::uniform_real_distribution<double> nudge(-0.1e-3, 0.1e-3);
  for (Vec3& p : s.position) p += Vec3{nudge(rng), nudge(rng), nudge(rng)};
  build_sphere_list(list, s, {}, d, 0.4e-3);
  std::size_t kept = 0;
  for (std::uint32_t i = 0; i < s.size(); ++i)
    for (std::uint32_t e = list.row_offset[i]; e < list.row_offset[i + 1]; ++e) {
      const auto before = set_to.find({i, list.neighbour[e]});
      const Vec3 expected = before == set_to.end() ? Vec3{} : before->second;
      kept += before != set_to.end();
      EXPECT_EQ(list.spring[e].x, expected.x);
      EXPECT_EQ(list.spring[e].y, expected.y);
      EXPECT_EQ(list.spring[e].z, expected.z);
    }
  EXPECT_GT(kept, list.pair_count() / 2);
}

TEST(SphereList, FindsThePlatesWithinReach) {
  Spheres s;
  s.add({.position = {0.5, 0.5, 0.0105}, .radius = 0.01, .mass = 1.0, .inertia = 1.0});
  s.add({.position = {0.5, 0.5, 0.5}, .radius = 0.01, .mass = 1.0, .inertia = 1.0});
  // a plate 0.2 m wide at x = 0.0105 m from the first sphere's side: its edge is in reach
  std::vector<Plane> plates = box_planes({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0});
  plates.push_back(make_plane({0.6 + 0.0105, 0.5, 0.0105}, {0.0, 0.0, 1.0}, 0.1, 0.1));
  SphereList list;
  build_sphere_list(list, s, plates, Domain3{}, 0.002);
  ASSERT_EQ(list.plate_offset.size(), 3u);
  EXPECT_EQ(list.plate_offset[1], 2u); // the floor and the plate's edge
  EXPECT_EQ(list.plate[0], 4u);
  EXPECT_EQ(list.plate[1], 6u);
  EXPECT_EQ(list.plate_offset[2], 2u); // the middle sphere: none
}

TEST(SphereList, RefusesAPeriodicAxisTooShortForItsImages) {
  std::mt19937 rng(3);
  Spheres s = random_spheres(20, rng);
  Domain3 d{.lo = {0.0, 0.0, 0.0}, .hi = {box, 5e-3, box}, .periodic = {false, true, false}};
  SphereList list;
  try {
    build_sphere_list(list, s, {}, d, 0.3e-3);
    FAIL() << "a 5 mm period with 2.7 mm ranges was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("at least 3 interaction ranges"), std::string::npos);
  }
}

} // namespace
} // namespace talus
