// The freezing-front frost model (frost/frost_front.hpp) on a small bed of fines, with and
// without a stone: the checks of docs/experiments.md, "Frost heave: the front model".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <tuple>
#include <vector>

#include "frost/frost_front.hpp"
#include "scenario/build.hpp"
#include "scenario/file/load.hpp"

namespace talus {
namespace {

// Fines of R = 0.5 mm +- 0.1 mm sedimented in a box 3 cm wide (one thread: the tests run side
// by side). Cached: each test builds it once. Every grain is a disk (m = rho pi r^2 x 1 m), so a
// stone presses the bed per unit width as a 2D grain should: with "sphere" masses a stone ten
// fines wide weighs a thousand fines but rests on about ten, and sinks through a loosened bed
// (docs/experiments.md). The stiffness is 1500 times the spheres' 2e3 N/m, as the masses are:
// the same collision time and overlaps.
const BuiltScenario& fines() {
  static const BuiltScenario b = build_scenario(load_scenario(R"(
name = "frost_front_test"
[simulation]
duration = 1.0
gravity = [0.0, -9.81]
tangential_law = "cundall_strack"
timestep_factor = 20
threads = 1
seed = 3
sort_every = 0 # the front model keeps its grains by index
[[materials]]
name = "soil"
density = 2650.0
normal_stiffness = 3.0e6
restitution = 0.3
friction = 0.5
[particles]
shape = "disk"
count = 560
size = { distribution = "uniform", mean_radius = 0.0005, spread = 0.0001 }
[packing]
method = "sedimentation"
settle_energy = 1.0e-7
settle_max_time = 0.3
[geometry]
builder = "box"
width = 0.03
height = 0.06
)",
                                                              "frost_front_test"));
  return b;
}

double bed_top(const Particles& p) {
  std::vector<double> top;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i)) top.push_back(p.position[i].y + p.radius[i]);
  std::sort(top.begin(), top.end());
  return top[top.size() * 95 / 100]; // the 95th percentile: a loose grain on top does not count
}

// The fines with a stone of radius R (0: none) set into the bed at x (its middle by default), its
// top `depth` below the surface (the fines it overlaps removed), at rest.
World with_stone(double radius, double depth, double x = 0.015) {
  World w = fines().world;
  if (radius <= 0.0) return w;
  const Vec2 centre{x, bed_top(w.particles) - depth - radius};
  World out;
  out.materials = w.materials;
  out.materials.push_back(out.materials[0]); // 1: thawed, wet soil (for frost.thawed_material)
  out.materials[1].name = "mud";
  out.materials[1].friction = 0.05;
  out.walls = w.walls;
  out.gravity = w.gravity;
  out.domain = w.domain;
  out.disk_thickness = w.disk_thickness;
  const Particles& p = w.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (norm(p.position[i] - centre) > radius + p.radius[i])
      out.add_particle({.position = p.position[i],
                        .radius = p.radius[i],
                        .material = p.material[i],
                        .kind = p.kind[i],
                        .mass = p.mass[i],
                        .inertia = p.inertia[i]});
  out.add_particle({.position = centre, .radius = radius, .shape = Shape::disk});
  return out;
}

struct Outcome {
  double stone_rise = 0.0;      ///< m over the cycles (centre height after - before)
  double stone_lift = 0.0;      ///< m: centre height at the end of the first freeze - before
  double surface_change = 0.0;  ///< m: the bed's top after - before
  double fine_drift = 0.0;      ///< m: mean |displacement| of the fines
  double stone_top_depth = 0.0; ///< m below the surface at the start
  double ice_content = 0.0;     ///< of the frozen fines in the first freeze
  double duration = 0.0;        ///< s from the first freeze's start to the end
  /// m: how far the front ran ahead in the stone's column during the first freeze: its depth
  /// there less the mean over the other columns, averaged over the freeze's samples
  double front_lead = 0.0;
};

void settle(Simulation& sim, double seconds) {
  sim.run(static_cast<std::uint64_t>(seconds / sim.config().timestep));
}

// n freeze-thaw cycles, each followed by 0.06 s of settling; with control_time > 0 that much time
// passes without frost instead (a control: what the grains do anyway).
Outcome cycles(World w, FrostFrontParameters q, int n, double control_time = 0.0) {
  const bool frost = control_time <= 0.0;
  Simulation sim(std::move(w), fines().config);
  settle(sim, 0.25);
  const Particles& p = sim.world().particles;
  std::size_t stone = p.size();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.radius[i] >= q.stone_radius) stone = i;
  Outcome o;
  const double top0 = bed_top(p);
  const double y0 = stone < p.size() ? p.position[stone].y : 0.0;
  if (stone < p.size()) o.stone_top_depth = top0 - (y0 + p.radius[stone]);
  const std::vector<Vec2> start = p.position;
  FrostFront front(q);
  const double t0 = sim.time();
  if (!frost) settle(sim, control_time);
  const std::size_t column = stone < p.size() ? front.column_of(p.position[stone].x) : 0;
  double lead_sum = 0.0;
  std::size_t lead_samples = 0;
  for (int c = 0; c < n && frost; ++c) {
    front.start_freeze(sim);
    int phases = 0;
    while (phases < 2) {
      sim.run(20);
      const bool ended = front.advance(sim);
      const std::vector<double>& depth = front.front_depth();
      if (c == 0 && phases == 0 && stone < p.size() && column < depth.size() && depth.size() > 1) {
        double others = 0.0;
        for (std::size_t k = 0; k < depth.size(); ++k)
          if (k != column) others += depth[k];
        lead_sum += depth[column] - others / static_cast<double>(depth.size() - 1);
        ++lead_samples;
      }
      if (ended) {
        ++phases;
        if (c == 0 && phases == 1 && stone < p.size()) o.stone_lift = p.position[stone].y - y0;
        if (c == 0 && phases == 1) o.ice_content = front.ice_content();
        if (std::getenv("TALUS_FROST_DEBUG") && stone < p.size()) {
          std::printf("  phase %d ended: stone y %+.3f mm; heave", phases,
                      1e3 * (p.position[stone].y - y0));
          for (const double h : front.heave()) std::printf(" %.3f", 1e3 * h);
          std::printf(" mm; front");
          for (const double d : front.front_depth()) std::printf(" %.2f", 1e3 * d);
          std::printf(" mm\n");
        }
      }
    }
    settle(sim, 0.06);
  }
  o.duration = sim.time() - t0;
  if (lead_samples > 0) o.front_lead = lead_sum / static_cast<double>(lead_samples);
  o.surface_change = bed_top(p) - top0;
  if (stone < p.size()) o.stone_rise = p.position[stone].y - y0;
  double drift = 0.0;
  std::size_t fines = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i) && i != stone) drift += norm(p.position[i] - start[i]), ++fines;
  o.fine_drift = drift / static_cast<double>(fines);
  return o;
}

FrostFrontParameters parameters(double depth) {
  FrostFrontParameters q;
  q.permafrost_depth = depth;
  q.heave_strain = 0.3;
  q.conductivity_ratio = 3.0;
  q.column_width = 0.01;
  q.crust_length = 0.01;
  q.stone_radius = 0.002;
  q.freeze_time = 0.15;
  q.thaw_time = 0.15;
  q.x_min = 0.0;
  q.x_max = 0.03;
  return q;
}

// After a full cycle without stones the surface comes back to its height within a grain
// diameter (1 mm; the thawed bed packs a little tighter) and the fines do not wander: on average
// less than a radius (0.5 mm).
TEST(FrostFront, WithoutStonesTheSurfaceComesBackAndTheFinesStay) {
  const Outcome o = cycles(with_stone(0.0, 0.0), parameters(0.015), 1);
  std::printf("no stones: surface %+.3f mm, fines moved %.3f mm on average\n",
              1e3 * o.surface_change, 1e3 * o.fine_drift);
  EXPECT_LT(std::abs(o.surface_change), 1e-3);
  EXPECT_LT(o.fine_drift, 0.5e-3);
}

// The ice content of the frozen fines, by default their pore fraction in the bed: a disordered
// packing of disks is no denser than random close packing, area fraction 0.840 for narrow size
// distributions like this one (Meer, Galoustian, de Falco Manuel and Weeks, arXiv:2404.02316,
// 2024), so the pores are at least 0.16; a sediment of frictional disks (mu = 0.5) packs looser,
// and 0.23 (area fraction 0.77) bounds it loosely from above (measured 0.181). A set value is
// used as given.
TEST(FrostFront, TheIceContentIsThePoreFractionOfTheFines) {
  Simulation sim(with_stone(0.0, 0.0), fines().config);
  FrostFrontParameters q = parameters(0.015);
  FrostFront measured(q);
  measured.start_freeze(sim);
  std::printf("ice content of the frozen fines: %.3f\n", measured.ice_content());
  EXPECT_GT(measured.ice_content(), 0.16);
  EXPECT_LT(measured.ice_content(), 0.23);
  q.ice_content = 0.45;
  FrostFront given(q);
  given.start_freeze(sim);
  EXPECT_EQ(given.ice_content(), 0.45);
  q.ice_content = 1.5;
  EXPECT_THROW(FrostFront{q}, InvalidArgument);
}

// Frozen grains feel no force from each other, so an overlap between two of them (here 10% of a
// radius, pressed in by hand after the freeze; in the window box a free grain shoved against a
// frozen one froze with 9%) would burst out at the thaw: a fine was thrown out of the box at
// 1.3 m/s. Thawed grains are moved apart first, so nothing moves much faster than the grains
// falling into the lenses of this quick cycle do without the pressed pair (0.098 m/s): measured
// 0.100 m/s, against 0.764 m/s without the separation. Bound 0.15 m/s.
TEST(FrostFront, GrainsFrozenIntoEachOtherThawOutGently) {
  Simulation sim(with_stone(0.0, 0.0), fines().config);
  FrostFrontParameters q = parameters(0.015);
  q.freeze_time = 0.01;
  q.thaw_time = 0.01;
  FrostFront front(q);
  front.start_freeze(sim);
  while (!front.advance(sim)) sim.run(20);
  const Particles& p = sim.world().particles;
  std::size_t top = 0; // the highest frozen fine, pressed into the frozen one below it
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!p.is_free(i) && p.position[i].y > p.position[top].y) top = i;
  std::size_t below = p.size();
  double nearest = 1e300;
  for (std::size_t j = 0; j < p.size(); ++j) {
    if (j == top || p.is_free(j) || p.position[j].y >= p.position[top].y) continue;
    const double gap = norm(p.position[j] - p.position[top]) - p.radius[j] - p.radius[top];
    if (gap < nearest) nearest = gap, below = j;
  }
  ASSERT_LT(below, p.size());
  const Vec2 axis =
      (p.position[below] - p.position[top]) / norm(p.position[below] - p.position[top]);
  sim.edit_particles().displace_held(static_cast<std::uint32_t>(top),
                                     axis * (nearest + 0.1 * p.radius[top]));
  double fastest = 0.0;
  for (bool done = false; !done;) {
    sim.run(20);
    done = front.advance(sim);
    for (std::size_t i = 0; i < p.size(); ++i) fastest = std::max(fastest, norm(p.velocity[i]));
  }
  std::printf("fastest grain during the thaw: %.3f m/s\n", fastest);
  EXPECT_LT(fastest, 0.15);
}

// The frost-pull estimate of a stone's rise: the heave of the fines frozen beside it while the
// frozen layer grips it, heave strain x min(2R, D - a) for a stone of radius R, top a deep.
double frost_pull_estimate(const FrostFrontParameters& q, double radius, double top_depth) {
  return q.heave_strain * std::clamp(q.permafrost_depth - top_depth, 0.0, 2.0 * radius);
}

struct OneStone {
  double lift = 0.0, estimate = 0.0, rise = 0.0; ///< m; rise: after the cycle, less a control's
  double ice_content = 0.0;
  double front_lead = 0.0; ///< m: Outcome::front_lead
};

// One cycle for a stone of radius R set with its top `depth` below the surface, against a control
// run that spends the same time without frost (a stone set into settled fines keeps sinking a
// little into the loosened ring around it). The control depends only on the stone, its place and
// the cycle's length (to 10 ms; the thaw lasts until the stone's cavity ice has gone), so runs
// that vary the frost model share it.
OneStone one_stone(const std::string& label, double radius, double depth, FrostFrontParameters q,
                   double x = 0.015) {
  static std::map<std::tuple<double, double, double, long>, double> control_rise;
  const Outcome o = cycles(with_stone(radius, depth, x), q, 1);
  const auto key = std::tuple{radius, depth, x, std::lround(o.duration / 0.01)};
  if (!control_rise.contains(key))
    control_rise[key] =
        cycles(with_stone(radius, depth, x), q, 1, 0.01 * static_cast<double>(std::get<3>(key)))
            .stone_rise;
  const OneStone s{o.stone_lift, frost_pull_estimate(q, radius, o.stone_top_depth),
                   o.stone_rise - control_rise[key], o.ice_content, o.front_lead};
  std::printf(
      "%-12s x %.1f mm, R %.1f mm, top %5.2f mm deep: lifted %6.3f mm by the freeze (estimate %.3f "
      "mm), rose %6.3f mm over the cycle against the control (%.0f%%; ice content %.3f; front "
      "%+.2f mm ahead in its column)\n",
      label.c_str(), 1e3 * x, 1e3 * radius, 1e3 * o.stone_top_depth, 1e3 * s.lift, 1e3 * s.estimate,
      1e3 * s.rise, 100.0 * s.rise / s.estimate, s.ice_content, 1e3 * s.front_lead);
  return s;
}

// The mean of f over the three places.
template <class F> double over_places(const std::vector<double>& places, F f) {
  double sum = 0.0;
  for (const double x : places) sum += f(x);
  return sum / static_cast<double>(places.size());
}

const std::vector<double> places{0.0125, 0.015, 0.0175}; // x, m: three packings around a stone

// One stone (R = 5 mm, ten fine radii) with its top 6 mm below the surface and its bottom below
// the front (15 mm down), heave strain 0.3, set at three places across the bed (three packings
// around it). Measured values in docs/experiments.md. What a cycle leaves a stone depends on the
// packing around it: the rise scatters from place to place by about a tenth of the estimate, and
// a change in the grains' contact laws (their tangential stiffness, say) redraws every packing.
// So the cycle is judged on the mean over the places; the freeze, which the packing hardly
// touches, at each place.
// - The freeze: the frozen layer grips the stone and the heave of the fines beside it lifts it
//   off the unfrozen fines it rested on, by the frost-pull estimate heave strain x (D - a) within
//   20% at each place (the fines' share of what the front crosses is below 1 near the loose
//   surface). The same for a larger stone (R = 7 mm, top 2 mm down).
// - The cycle: the stone rests on the ice in its cavity, which holds 1 / ice_content times the
//   latent heat of as much frozen soil (ice content: the bed's pore fraction, 0.19), until the
//   thaw has gone through it, while the thawed fines beside it slump under it. With these dry
//   fines it keeps more than 70% of the estimate on average (the issue's 20% is checked with wet
//   fines in OneStoneInSaturatedFinesKeepsItsLift). Frost pull is what keeps it: released by its
//   centre instead, the stone keeps at least 1 mm less on average.
// - The thermal contrast does what the model says it does: the front runs ahead in the stone's
//   column (dry stones conduct three times as well and hold no water), at each place, by more
//   than a fine's diameter (1 mm) on average over the freeze; without the contrast it runs level
//   (within a fine's radius). What that does to the rise over the cycle is printed, not asserted:
//   it is smaller than the place-to-place scatter, and its sign follows the packing.
// - A stone below the freezing depth is neither lifted (0.2 mm) nor moved by the cycle (0.1 mm).
// Printed only: the cavity ice thawing like frozen soil (ice content 1).
// Opt-in (3 minutes): TALUS_LONG_TESTS=1.
TEST(LongFrostFront, TheFreezeLiftsAStoneAndFrostPullKeepsItsLift) {
  if (!std::getenv("TALUS_LONG_TESTS")) GTEST_SKIP() << "long: set TALUS_LONG_TESTS=1";
  const FrostFrontParameters q = parameters(0.015);
  FrostFrontParameters level = q; // no thermal contrast: a level front (frost pull alone)
  level.conductivity_ratio = 1.0;
  level.stone_water = 1.0;
  FrostFrontParameters centre = q; // stones thaw out by their centre
  centre.frost_pull = false;
  FrostFrontParameters soil_ice = q; // the cavity's ice thaws like frozen soil
  soil_ice.ice_content = 1.0;
  std::map<std::string, double> mean_rise;
  double mean_estimate = 0.0;
  for (const double x : places) {
    const OneStone s = one_stone("default", 0.005, 0.006, q, x);
    EXPECT_NEAR(s.lift, s.estimate, 0.2 * s.estimate) << "x = " << x;
    mean_estimate += s.estimate / 3.0;
    mean_rise["default"] += s.rise / 3.0;
    const OneStone flat = one_stone("no contrast", 0.005, 0.006, level, x);
    EXPECT_GT(s.front_lead, 1e-3) << "x = " << x;
    EXPECT_LT(std::abs(flat.front_lead), 0.5e-3) << "x = " << x;
    mean_rise["no contrast"] += flat.rise / 3.0;
    mean_rise["no pull"] += one_stone("no pull", 0.005, 0.006, centre, x).rise / 3.0;
    mean_rise["soil-like ice"] += one_stone("soil ice", 0.005, 0.006, soil_ice, x).rise / 3.0;
  }
  for (const auto& [label, rise] : mean_rise)
    std::printf("mean rise over the three places, %s: %.3f mm (%.0f%% of the mean estimate)\n",
                label.c_str(), 1e3 * rise, 100.0 * rise / mean_estimate);
  EXPECT_GT(mean_rise["default"], 0.7 * mean_estimate);
  EXPECT_GT(mean_rise["default"], mean_rise["no pull"] + 1e-3);
  const OneStone large = one_stone("larger", 0.007, 0.002, q); // its bottom below the front
  EXPECT_NEAR(large.lift, large.estimate, 0.2 * large.estimate);
  // below the freezing depth: the front stops 5 mm down, the stone's top is 8 mm down (R = 3.5
  // mm, so that it clears the floor of the 18 mm deep bed)
  const OneStone deep = one_stone("deep", 0.0035, 0.008, parameters(0.005));
  EXPECT_LT(std::abs(deep.lift), 0.2e-3);
  EXPECT_LT(std::abs(deep.rise), 0.1e-3);
}

// The issue's checks on the whole cycle in saturated fines: the cavity ice against the pore ice
// of the bed (ice content = its pore fraction, the default) and thawed fines wet and weak
// (frost.thawed_material, friction 0.05: Washburn's fines that slump or are washed into the
// cavity). Judged on the means over the three places, as above.
// - The stone of the test above (gripped, its bottom below the front) rises by the frost-pull
//   estimate within 20%.
// - With frost pull alone (a level front), stones of R = 3.5, 5 and 7 mm with their tops 2 mm
//   down rise by the estimate 0.3 x min(2R, D - a) within 20%, and larger stones rise more.
// Printed only: the same stones with the thermal contrast, where the front runs through the
// column of a stone as wide as it (R = 5 mm) and freezes the fines under it before a cavity opens
// (docs/experiments.md).
// Opt-in (6 minutes): TALUS_LONG_TESTS=1.
TEST(LongFrostFront, OneStoneInSaturatedFinesKeepsItsLift) {
  if (!std::getenv("TALUS_LONG_TESTS")) GTEST_SKIP() << "long: set TALUS_LONG_TESTS=1";
  FrostFrontParameters q = parameters(0.015);
  q.thawed_material = 1;
  double rise = 0.0, estimate = 0.0;
  for (const double x : places) {
    const OneStone s = one_stone("saturated", 0.005, 0.006, q, x);
    rise += s.rise / 3.0, estimate += s.estimate / 3.0;
  }
  std::printf("saturated: mean rise %.3f mm, %.0f%% of the mean estimate\n", 1e3 * rise,
              100.0 * rise / estimate);
  EXPECT_NEAR(rise, estimate, 0.2 * estimate);
  FrostFrontParameters level = q; // frost pull alone: a level front
  level.conductivity_ratio = 1.0;
  level.stone_water = 1.0;
  double smaller = 0.0;
  for (const double radius : {0.0035, 0.005, 0.007}) {
    double mean = 0.0, mean_estimate = 0.0;
    for (const double x : places) {
      const OneStone s = one_stone("size", radius, 0.002, level, x);
      mean += s.rise / 3.0, mean_estimate += s.estimate / 3.0;
    }
    std::printf("R = %.1f mm: mean rise %.3f mm, %.0f%% of the mean estimate\n", 1e3 * radius,
                1e3 * mean, 100.0 * mean / mean_estimate);
    EXPECT_NEAR(mean, mean_estimate, 0.2 * mean_estimate) << "R = " << radius;
    EXPECT_GT(mean, smaller) << "R = " << radius;
    smaller = mean;
    const double contrast = over_places(
        places, [&](double x) { return one_stone("size+contrast", radius, 0.002, q, x).rise; });
    std::printf("R = %.1f mm with the thermal contrast: mean rise %.3f mm, %.0f%%\n", 1e3 * radius,
                1e3 * contrast, 100.0 * contrast / mean_estimate);
  }
}

} // namespace
} // namespace talus
