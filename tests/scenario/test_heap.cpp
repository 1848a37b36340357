// The built-in heap: a column of grains released onto a floor slumps into a heap, whose angle of
// repose (post/repose.hpp) grows with the grains' rolling resistance. Round grains without it roll
// on and spread nearly flat.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "analysis/frame.hpp"
#include "cli/run/run_loop.hpp"
#include "io/checkpoint.hpp"
#include "post/repose.hpp"
#include "scenario/build.hpp"
#include "support/builtin_scenario.hpp"
#include "support/run_dir.hpp"

namespace fs = std::filesystem;

namespace talus {
namespace {

// The heap of half the built-in's grains, in a column half as wide (as tall for its width, so
// that it still collapses), with rolling resistance mu_r: its angle of repose, deg.
double heap_angle(double mu_r) {
  const Scenario s = testing::builtin(
      "heap", {"particles.count=150", "geometry.width=0.03", "geometry.segments.0.a=[0.03,0.0]",
               "stages.2.duration=1.0", "materials.0.rolling_friction=" + std::to_string(mu_r),
               "output.snapshot_interval=0", "output.pictures=[]", "output.picture=false"});
  const fs::path dir = testing::fresh_dir("heap");
  cli::RunOptions o;
  o.quiet = true;
  EXPECT_EQ(cli::start_run(s, build_scenario(s), dir.string(), o), cli::exit_completed);
  std::ifstream in(dir / "checkpoint.bin", std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const Checkpoint c = decode_checkpoint(bytes, "heap");
  const ReposeProfile p = repose_profile(frame_of(Simulation::restore(c.state, c.config)));
  fs::remove_all(dir);
  return p.angle_deg;
}

TEST(Heap, ItsAngleOfReposeGrowsWithRollingResistance) {
  const double none = heap_angle(0.0), some = heap_angle(0.4);
  std::printf("angle of repose: %.1f deg without rolling resistance, %.1f deg with mu_r = 0.4\n",
              none, some);
  // without it the grains spread into a layer a grain or two deep: a slope of a few degrees
  EXPECT_LT(none, 5.0);
  // with it they stand as a heap, steeper by a margin that no other packing of the column (the
  // seed) comes near (docs/validation.md has the angles)
  EXPECT_GT(some, none + 10.0);
}

} // namespace
} // namespace talus
