// Simple shear in a sheared (Lees-Edwards) cell at a normal stress (the built-in `simple_shear`):
// the cell holds sigma_yy while it shears, the grains' velocity profile is the cell's shear rate
// across the whole height (no wall, no band), and the rheology analysis measures mu, phi and I
// from the cell's stress (post/rheology.hpp, cell_rheology_point).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "cli/analyze/analyses.hpp"
#include "support/builtin_scenario.hpp"
#include "support/run_dir.hpp"
#include "support/run_scenario.hpp"
#include "support/thermo_rows.hpp"

namespace talus {
namespace {

using testing::mean_of;

// 2 s of the built-in at a shear rate of 4 1/s (the lattice is pressed within about 0.5 s; then
// I is about 0.2). Over the second half:
// - sigma_yy, contact and kinetic parts, is the 100 N/m the cell holds within 1% (100 rows of a
//   400-grain cell sample its fluctuations of a few percent), and the analysis reads the same;
// - the slope of the grains' v_x over y is the cell's rate within 5 standard errors and 10%: the
//   images drive the whole height, where walls would leave layers by them slipping;
// - mu is between 0.33 and 0.5 (the plane shear's sweep, docs/experiments.md, gives 0.42 at
//   I = 0.17 and 0.39 at I = 0.13) and phi between 0.74 and 0.79 (0.764 and 0.777 there).
TEST(SimpleShear, TheCellHoldsItsNormalStressAndShearsUniformly) {
  const Scenario s = testing::builtin(
      "simple_shear", {"simulation.duration=2", "drivers.0.shear_rate=4", "output.pictures=[]"});
  const std::filesystem::path dir = testing::fresh_dir("simple_shear");
  ASSERT_EQ(testing::run_quietly(s, dir), cli::exit_completed);
  const auto rows = testing::thermo_rows(dir);
  // thermo.csv's stress_yy is the contact part: the cell holds it with the kinetic part
  const double held = mean_of(rows, "stress_yy", 1.0) + mean_of(rows, "kinetic_stress_yy", 1.0);
  EXPECT_NEAR(held, 100.0, 1.0);
  EXPECT_NEAR(rows.back().at("cell_shear_strain"), 4.0 * rows.back().at("time"), 1e-6);

  cli::RunData run(dir);
  const RheologyPoint r = cli::run_rheology(run, cli::AnalysisOptions{});
  ASSERT_TRUE(r.measured) << r.why_not;
  EXPECT_EQ(r.shear_rate, 4.0);
  EXPECT_NEAR(r.pressure, held, 0.01 * held); // the same rows, kinetic part included
  EXPECT_NEAR(r.profile_shear_rate, 4.0, std::max(0.4, 5.0 * r.profile_shear_rate_error));
  EXPECT_LT(std::abs(r.profile_shear_rate - 4.0), 0.4);
  EXPECT_GT(r.friction, 0.33);
  EXPECT_LT(r.friction, 0.5);
  EXPECT_GT(r.packing, 0.74);
  EXPECT_LT(r.packing, 0.79);
  EXPECT_GT(r.inertial, 0.1);
  EXPECT_LT(r.inertial, 0.3);
}

} // namespace
} // namespace talus
