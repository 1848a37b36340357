// The thesis' experiments (ch. 4), shortened so they run in seconds: the built-in scenarios with
// fewer grains and less time, observed in process with the same analyses `talus analyze` uses.
// Full runs and their numbers: docs/experiments.md. Tolerances are stated where they are used.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "analysis/force_distribution.hpp"
#include "analysis/frame.hpp"
#include "post/discharge.hpp"
#include "post/flow_profiles.hpp"
#include "post/segregation.hpp"
#include "scenario/build.hpp"
#include "scenario/file/load.hpp"
#include "scenario/geometry.hpp"
#include "support/builtin_scenario.hpp"

namespace talus {
namespace {

using testing::builtin;

// Runs a scenario to its duration, keeping a frame every `interval` seconds (and at the start).
std::vector<Frame> frames_of(const Scenario& s, double interval) {
  BuiltScenario b = build_scenario(s);
  Simulation sim(std::move(b.world), b.config);
  const auto every = static_cast<std::uint64_t>(std::llround(interval / b.config.timestep));
  const auto total =
      static_cast<std::uint64_t>(std::ceil(s.simulation.duration / b.config.timestep));
  std::vector<Frame> frames{frame_of(sim)};
  for (std::uint64_t k = 1; k <= total; ++k) {
    sim.step();
    if (k % every == 0) frames.push_back(frame_of(sim));
  }
  return frames;
}

// Thesis 4.1: grains leave the hourglass' upper bulb fastest on the centre line, the grains by
// the funnel walls barely move, and the flow rate does not depend on the fill height (Beverloo).
TEST(Experiments, HourglassFlowsFastestOnTheCentreLineAtASteadyRate) {
  const Scenario s = builtin("hourglass", {"particles.count=250", "simulation.duration=0.8",
                                           "packing.settle_max_time=0.6"});
  const auto frames = frames_of(s, 0.01);
  // the band just above the orifice (y = 0), 2 orifice widths high, bins of 2 cm across
  const BandProfile p = band_profile(frames, 0.0, 0.1, 0.0, 0.42, 21);
  std::size_t first = 21, last = 0;
  for (std::size_t b = 0; b < 21; ++b)
    if (p.count[b] > 0) first = std::min(first, b), last = std::max(last, b);
  ASSERT_LT(first, last);
  const double centre = p.vy[10], edges = 0.5 * (p.vy[first] + p.vy[last]);
  EXPECT_LT(centre, -0.1) << "grains fall through the orifice";
  // slow by the walls: the edge bins move at under half the centre's speed. Measured over
  // seeds 1 to 8 (frames every 0.01 s, 80 to 115 samples in an edge bin): the centre is 2.6 to
  // 3.4 times faster than the edges; the ratio is a property of the realization (the settled
  // packing and the flow are chaotic), so the bound leaves room below the lowest seen.
  EXPECT_LT(std::abs(edges), std::abs(centre) / 2.0) << "centre " << centre << ", edges " << edges;

  const auto [x0, x1] = orifice_span(s.geometry);
  const Discharge q = discharge(frames, Orifice{0.0, x0, x1});
  std::printf("hourglass: v_y centre %.3f m/s, edges %.3f m/s (%zu, %zu samples); %.1f grains/s "
              "(halves %.1f, %.1f)\n",
              centre, edges, p.count[first], p.count[last], q.rate, q.rate_first_half,
              q.rate_second_half);
  EXPECT_GT(q.rate, 0.0);
  // steady: the rates over the two halves of the flow agree within 35% (some 150 grains per
  // half: counting noise alone is about 10%; the rest allows for the start of the flow)
  EXPECT_NEAR(q.rate_first_half / q.rate_second_half, 1.0, 0.35)
      << q.rate_first_half << " vs " << q.rate_second_half << " grains/s";
}

// Thesis 4.3: compressed past jamming, most contacts carry less than the mean force and the
// forces above the mean fall off exponentially, P(f) ~ exp(-beta f/<f>).
TEST(Experiments, CompressedPackingHasAnExponentialForceTail) {
  // 250 grains in a shallower press, the lid twice as fast: jammed after 0.5 s, not 2.4 s
  const Scenario s =
      builtin("force_network", {"particles.count=250", "geometry.height=0.18",
                                "geometry.lid_speed=0.2", "simulation.duration=0.54"});
  const auto frames = frames_of(s, 0.02);
  std::vector<double> scaled; // the last three frames, each scaled by its own mean
  for (std::size_t k = frames.size() - 3; k < frames.size(); ++k) {
    double mean = 0.0;
    std::size_t n = 0;
    for (const auto& c : frames[k].chains)
      if (c.force > 0.0) mean += c.force, ++n;
    ASSERT_GT(n, 250u) << "jammed: more than one contact per grain";
    mean /= static_cast<double>(n);
    for (const auto& c : frames[k].chains)
      if (c.force > 0.0) scaled.push_back(c.force / mean);
  }
  const ForceDistribution d = force_distribution(scaled);
  std::printf("force network: %zu contacts, %.1f%% below the mean, beta = %.2f +- %.2f over %.2f "
              "to %.2f\n",
              d.contacts, 100.0 * d.fraction_below_mean, d.beta, d.beta_error, d.fit_from,
              d.fit_to);
  // "most": a symmetric distribution has 50% below its mean, an exponential 1 - 1/e = 63%; with
  // some 1700 contacts the share's counting error is 1.2%, so 53% is more than two errors above
  // a symmetric one (the full run gives 60 to 65%: docs/experiments.md)
  EXPECT_GT(d.fraction_below_mean, 0.53);
  ASSERT_GE(d.fit_bins, 3u);
  // literature: beta about 1.4 to 1.9 (Radjai et al. 1996; Mueth et al. 1998); small packings
  // just past jamming give lower values (docs/experiments.md): accept 0.7 to 2.5, and a fit
  // good to 25%
  EXPECT_GT(d.beta, 0.7);
  EXPECT_LT(d.beta, 2.5);
  EXPECT_LT(d.beta_error, 0.25 * d.beta);
}

// Thesis 4.2, the full built-in run (8 s, about 2.5 min): the small grains go down by the rough
// walls and up in the middle (convection rolls, fig. 4.11), and the large disk climbs from the
// bottom to the top layer and stays there. Opt-in: TALUS_LONG_TESTS=1 (scripts/test.sh --long).
TEST(LongExperiments, ShakenSiloLiftsTheLargeDiskToTheTopAndKeepsItThere) {
  if (!std::getenv("TALUS_LONG_TESTS")) GTEST_SKIP() << "long: set TALUS_LONG_TESTS=1";
  const Scenario s = builtin("silo_shake", {});
  const auto frames = frames_of(s, 0.1); // the shaking's period: every frame at one phase
  const SegregationSeries g = segregation(frames);
  ASSERT_EQ(g.large_count, 1u);
  const ConvectionProfile c = convection(frames, g.large_radius, 10);
  const double walls = 0.5 * (c.drift.front() + c.drift.back());
  const double middle = 0.5 * (c.drift[4] + c.drift[5]);
  std::printf("silo: index %.2f -> %.2f; drift by the walls %.4f m/s, middle %.4f m/s\n",
              g.index.front(), g.index.back(), walls, middle);
  EXPECT_LT(walls, 0.0);
  EXPECT_GT(middle, 0.0);
  EXPECT_GT(g.largest_depth_fraction.front(), 0.7) << "the disk starts at the bottom";
  // The last 1.5 s: on average the disk's top lies within a fifth of the bed height of the
  // surface (its own diameter is a sixth of the bed) and the index is well above mixed (0); at
  // no frame does it sink below 0.4 of the bed height. The shaken bed carries the disk up and
  // down by a few grain diameters: in two packings settled by two engine versions every frame
  // was within 0.2 in one, while the other dipped to 0.34 for a frame, so single frames are
  // held to the looser bound. A disk that stays low or sinks back (0.5 and more) fails.
  double depth = 0.0, index = 0.0, deepest = 0.0;
  const std::size_t first = frames.size() - 15;
  for (std::size_t k = first; k < frames.size(); ++k) {
    depth += g.largest_depth_fraction[k] / 15.0;
    index += g.index[k] / 15.0;
    deepest = std::max(deepest, g.largest_depth_fraction[k]);
  }
  std::printf("silo, last 1.5 s: depth fraction %.3f on average, %.3f at the deepest; index "
              "%.3f\n",
              depth, deepest, index);
  EXPECT_LT(depth, 0.2);
  EXPECT_LT(deepest, 0.4);
  EXPECT_GT(index, 0.3);
}

} // namespace
} // namespace talus
