// The plan of a parameter sweep (cli/sweep/sweep.hpp): what each run is to run with.
#include <gtest/gtest.h>

#include "cli/sweep/sweep.hpp"

namespace talus::cli {

// The index reports each run's seed; a varied simulation.seed is the seed those runs run with,
// not the scenario's.
TEST(SweepPlan, EachRunsSeedIsTheOneItRunsWith) {
  const SweepPlan varied = plan_sweep("collisions", {}, {parse_axis("simulation.seed=1,2")}, 1);
  ASSERT_EQ(varied.runs.size(), 2u);
  EXPECT_EQ(varied.runs[0].seed, 1u);
  EXPECT_EQ(varied.runs[1].seed, 2u);
  for (const SweepRun& r : varied.runs)
    EXPECT_EQ(sweep_run_scenario(varied, r).simulation.seed, r.seed) << r.name;

  const SweepPlan seeds = plan_sweep("collisions", {"simulation.seed=7"},
                                     {parse_axis("simulation.duration=0.1,0.2")}, 2);
  ASSERT_EQ(seeds.runs.size(), 4u);
  const std::uint64_t expected[] = {7, 8, 7, 8};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(seeds.runs[k].seed, expected[k]) << seeds.runs[k].name;
    EXPECT_EQ(sweep_run_scenario(seeds, seeds.runs[k]).simulation.seed, expected[k]);
  }
}

} // namespace talus::cli
