// The plan of a parameter sweep (cli/sweep/sweep.hpp): what each run is to run with.
#include <gtest/gtest.h>

#include "cli/analyze/analyses.hpp"
#include "cli/sweep/sweep.hpp"
#include "scenario/file/load.hpp"
#include "talus/error.hpp"

namespace talus::cli {

// The index reports each run's seed; a varied simulation.seed is the seed those runs run with,
// not the scenario's.
TEST(SweepPlan, EachRunsSeedIsTheOneItRunsWith) {
  const SweepPlan varied = plan_sweep("collisions", {}, {parse_axis("simulation.seed=1,2")}, 1);
  ASSERT_EQ(varied.runs.size(), 2u);
  EXPECT_EQ(varied.runs[0].seed, 1u);
  EXPECT_EQ(varied.runs[1].seed, 2u);
  for (const SweepRun& r : varied.runs)
    EXPECT_EQ(sweep_run_scenario(varied, r).seed, r.seed) << r.name;

  const SweepPlan seeds = plan_sweep("collisions", {"simulation.seed=7"},
                                     {parse_axis("simulation.duration=0.1,0.2")}, 2);
  ASSERT_EQ(seeds.runs.size(), 4u);
  const std::uint64_t expected[] = {7, 8, 7, 8};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(seeds.runs[k].seed, expected[k]) << seeds.runs[k].name;
    EXPECT_EQ(sweep_run_scenario(seeds, seeds.runs[k]).seed, expected[k]);
  }
}

// A vector's values: the commas inside brackets are the vector's; each run gets its vector.
TEST(SweepPlan, AVectorsValuesSplitAtTheCommasOutsideBrackets) {
  const SweepAxis a = parse_axis("simulation.gravity=[0,-9.81],[1.5, -9.7]");
  ASSERT_EQ(a.values.size(), 2u);
  EXPECT_EQ(a.values[0], "[0,-9.81]");
  EXPECT_EQ(a.values[1], "[1.5, -9.7]");
  const SweepPlan p = plan_sweep("collisions", {}, {a}, 1);
  EXPECT_DOUBLE_EQ(load_scenario(sweep_run_scenario(p, p.runs[1]).toml, "run").simulation.gravity.x,
                   1.5);
  EXPECT_THROW(parse_axis("simulation.gravity=[0,-9.81"), InvalidArgument);
  EXPECT_THROW(parse_axis("simulation.gravity=[0,-9.81],"), InvalidArgument); // an empty value
}

// Index and analysis CSV cells: a vector's value or a message with a comma is quoted, its quotes
// doubled (RFC 4180), so that a CSV reader reads back the one cell.
TEST(SweepPlan, CsvCellsWithCommasOrQuotesAreQuoted) {
  EXPECT_EQ(csv_cell("0.05"), "0.05");
  EXPECT_EQ(csv_cell("[2.87,-9.38]"), "\"[2.87,-9.38]\"");
  EXPECT_EQ(csv_cell("said \"no\", twice"), "\"said \"\"no\"\", twice\"");
}

} // namespace talus::cli
