// The Verlet list holds exactly the pairs within reach: compared with brute force on random,
// dense, polydisperse and periodic configurations. Contact history survives rebuilds.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <tuple>

#include "core/random.hpp"
#include "neighbours/cell_grid.hpp"
#include "neighbours/neighbour_list.hpp"
#include "simulation/simulation.hpp"
#include "talus/error.hpp"

namespace talus {
namespace {

using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

PairSet brute_force(const Particles& p, const Domain& d, double skin) {
  PairSet s;
  for (std::uint32_t i = 0; i < p.size(); ++i)
    for (std::uint32_t j = i + 1; j < p.size(); ++j) {
      if (!p.is_free(i) && !p.is_free(j)) continue;
      const double reach = p.radius[i] + p.radius[j] + skin;
      if (norm2(d.minimum_image(p.position[i], p.position[j])) < reach * reach) s.emplace(i, j);
    }
  return s;
}

PairSet listed(const NeighbourList& l) {
  PairSet s;
  for (std::uint32_t i = 0; i + 1 < l.row_offset.size(); ++i)
    for (std::uint32_t e = l.row_offset[i]; e < l.row_offset[i + 1]; ++e) {
      EXPECT_TRUE(s.emplace(i, l.neighbour[e]).second) << "pair listed twice";
    }
  return s;
}

struct Config {
  const char* name;
  std::size_t n;
  double r_min, r_max;
  double side;
  bool px, py;
};

class NeighbourListVsBruteForce : public ::testing::TestWithParam<Config> {};

TEST_P(NeighbourListVsBruteForce, FindsExactlyThePairsWithinReach) {
  const Config c = GetParam();
  Particles p;
  RandomStream rng(42, 1);
  for (std::size_t k = 0; k < c.n; ++k) {
    ParticleSpec s;
    s.position = {rng.uniform(0.0, c.side), rng.uniform(0.0, c.side)};
    s.radius = rng.uniform(c.r_min, c.r_max);
    s.mass = s.inertia = 1.0;
    s.kind = k % 17 == 0 ? Kind::fixed : Kind::free;
    p.add(s);
  }
  const Domain d{{0.0, 0.0}, {c.side, c.side}, c.px, c.py};
  for (const double skin : {0.0, 0.1 * c.r_max, c.r_max}) {
    NeighbourList l;
    build_neighbour_list(l, p, {}, d, skin);
    EXPECT_EQ(listed(l), brute_force(p, d, skin)) << c.name << ", skin " << skin;
    // deferred slots: exactly the entries whose second particle lies beyond the row's block,
    // numbered in entry order, each listed once under its second particle
    std::vector<std::uint32_t> later; // second particle of each deferred entry, in entry order
    for (std::uint32_t i = 0; i < p.size(); ++i) {
      const std::uint32_t block_end = std::min<std::uint32_t>(
          static_cast<std::uint32_t>(p.size()), (i / l.block_rows + 1) * l.block_rows);
      for (std::uint32_t e = l.row_offset[i]; e < l.row_offset[i + 1]; ++e)
        if (l.neighbour[e] >= block_end) later.push_back(l.neighbour[e]);
    }
    ASSERT_EQ(l.block_first_slot.back(), later.size());
    std::vector<int> seen(later.size(), 0);
    for (std::uint32_t k = 0; k < p.size(); ++k)
      for (std::uint32_t q = l.deferred_offset[k]; q < l.deferred_offset[k + 1]; ++q) {
        const std::uint32_t slot = l.deferred_slot[q];
        EXPECT_EQ(later[slot], k);
        if (q > l.deferred_offset[k]) {
          EXPECT_LT(l.deferred_slot[q - 1], slot);
        }
        ++seen[slot];
      }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(later.size()));
    // built in blocks by several threads: the same list, entry for entry
    NeighbourList many;
    build_neighbour_list(many, p, {}, d, skin, 3);
    EXPECT_EQ(many.row_offset, l.row_offset);
    EXPECT_EQ(many.neighbour, l.neighbour);
    EXPECT_EQ(many.deferred_slot, l.deferred_slot);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Configurations, NeighbourListVsBruteForce,
    ::testing::Values(Config{"random", 500, 0.01, 0.01, 1.0, false, false},
                      Config{"dense", 800, 0.02, 0.02, 1.0, false, false},
                      Config{"polydisperse", 600, 0.002, 0.04, 1.0, false, false},
                      Config{"periodic_x", 600, 0.005, 0.03, 1.0, true, false},
                      Config{"periodic_xy", 600, 0.005, 0.03, 1.0, true, true},
                      Config{"periodic_dense", 900, 0.015, 0.025, 0.8, true, true}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

// Large enough that the cell sort and the wall rows are built by several threads: the same grid
// and list, entry for entry, whatever the thread count (a box with a floor and a slanted wall,
// periodic in x, some particles outside the box to spread the cells unevenly).
TEST(NeighbourList, ManyThreadsBuildTheSameGridAndList) {
  Particles p;
  RandomStream rng(7, 3);
  for (std::size_t k = 0; k < 30000; ++k) {
    ParticleSpec s;
    const double y = k % 10 == 0 ? rng.uniform(0.0, 0.1) : rng.uniform(0.0, 1.0); // dense below
    s.position = {rng.uniform(0.0, 2.0), y};
    s.radius = rng.uniform(0.002, 0.006);
    s.mass = s.inertia = 1.0;
    s.kind = k % 23 == 0 ? Kind::fixed : Kind::free;
    p.add(s);
  }
  const Domain d{{0.0, 0.0}, {2.0, 1.0}, true, false};
  const Segments walls = {Segment{.a = {0.0, 0.003}, .b = {2.0, 0.003}},
                          Segment{.a = {0.5, 0.0}, .b = {0.9, 0.5}}};
  CellGrid one;
  one.build(p.position, d, 0.013, 1);
  NeighbourList l;
  build_neighbour_list(l, p, walls, d, 0.001, 1);
  ASSERT_GT(l.wall_segment.size(), 100U) << "the walls touch some grains";
  for (std::size_t c = 0; c + 1 < one.cell_start.size(); ++c)
    for (std::uint32_t k = one.cell_start[c]; k + 1 < one.cell_start[c + 1]; ++k)
      ASSERT_LT(one.items[k], one.items[k + 1]) << "ascending within cell " << c;
  for (const int threads : {2, 3, 5}) {
    CellGrid many;
    many.build(p.position, d, 0.013, threads);
    EXPECT_EQ(many.cell_start, one.cell_start) << threads << " threads";
    EXPECT_EQ(many.items, one.items) << threads << " threads";
    EXPECT_EQ(many.cell_of, one.cell_of) << threads << " threads";
    NeighbourList m;
    build_neighbour_list(m, p, walls, d, 0.001, threads);
    EXPECT_EQ(m.row_offset, l.row_offset) << threads << " threads";
    EXPECT_EQ(m.neighbour, l.neighbour) << threads << " threads";
    EXPECT_EQ(m.image, l.image) << threads << " threads";
    EXPECT_EQ(m.wall_offset, l.wall_offset) << threads << " threads";
    EXPECT_EQ(m.wall_segment, l.wall_segment) << threads << " threads";
    EXPECT_EQ(m.late, l.late) << threads << " threads";
  }
}

TEST(NeighbourList, RebuildsOnlyAfterHalfTheSkin) {
  Particles p;
  for (int k = 0; k < 3; ++k)
    p.add({.position = {0.1 * k, 0.0}, .radius = 0.01, .mass = 1.0, .inertia = 1.0});
  NeighbourList l;
  build_neighbour_list(l, p, {}, Domain{}, 0.02);
  p.position[1].x += 0.0099;
  EXPECT_FALSE(needs_rebuild(l, p, {}));
  p.position[1].x += 0.0002;
  EXPECT_TRUE(needs_rebuild(l, p, {}));
}

TEST(NeighbourList, PeriodicBoxTooSmallIsRefusedClearly) {
  Particles p;
  p.add({.position = {0.1, 0.1}, .radius = 0.1, .mass = 1.0, .inertia = 1.0});
  NeighbourList l;
  EXPECT_THROW(build_neighbour_list(l, p, {}, Domain{{0, 0}, {0.5, 0.5}, true, false}, 0.0),
               InvalidArgument);
}

// A grain resting on another keeps its tangential spring across many rebuilds, forced by
// jiggling a far-away grain: history belongs to the pair, not to the list.
TEST(NeighbourList, ContactHistorySurvivesRebuilds) {
  World w;
  Material m;
  m.normal_stiffness = 1.0e4;
  m.friction = 0.5;
  w.materials = {m};
  w.add_particle({.position = {0.0, 0.0}, .radius = 1e-3, .kind = Kind::fixed});
  w.add_particle({.position = {0.0, 1.999e-3}, .radius = 1e-3, .velocity = {1e-3, 0.0}});
  w.add_particle({.position = {0.1, 0.0}, .radius = 1e-3, .velocity = {5.0, 0.0}}); // far, fast
  SimulationConfig c;
  c.timestep = 1e-6;
  c.tangential_law = law_id<CundallStrack>;
  c.skin = 2.5e-4; // small, so that the fast grain forces rebuilds
  Simulation s(std::move(w), c);
  s.run(200);
  const auto& l = s.neighbours();
  ASSERT_GT(l.builds, 5U);
  // the pair (0, 1) is the first entry of row 0
  ASSERT_GT(l.row_offset[1], 0U);
  EXPECT_EQ(l.neighbour[0], 1U);
  EXPECT_GT(std::abs(l.history[0]), 1e-8); // spring stretched by the sliding grain
}

} // namespace
} // namespace talus
