// Tracks across periodic boundaries: the engine counts the boundaries each grain crosses (its
// image), so track.csv's unwrapped positions (xu, yu) follow the grain's motion, through a
// checkpoint and resume too, and the tracks analysis measures the distance it went.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/run/run_loop.hpp"
#include "io/checkpoint.hpp"
#include "io/track_csv.hpp"
#include "scenario/file/load.hpp"
#include "support/run_dir.hpp"

namespace fs = std::filesystem;

namespace talus {
namespace {

using testing::fresh_dir;

// A grain alone in a periodic 0.1 m box at (1, 0.25) m/s, 0.35 s: it crosses the x boundary
// three times and the y boundary once; another grain, at rest, is never met.
const char* const crossing = R"(
name = "crossing"
[simulation]
duration = 0.35
gravity = [0.0, 0.0]
[particles]
shape = "sphere"
[[particles.list]]
position = [0.05, 0.05]
radius = 0.002
velocity = [1.0, 0.25]
[[particles.list]]
position = [0.02, 0.08]
radius = 0.002
[geometry]
periodic = "xy"
box = [0.0, 0.0, 0.1, 0.1]
[track]
ids = [0]
[output]
track_interval = 0.01
)";

int run(const fs::path& dir, double stop_at = -1.0) {
  const Scenario s = load_scenario(crossing, "crossing.toml");
  cli::RunOptions o;
  o.quiet = true;
  o.stop_at = stop_at;
  return cli::start_run(s, build_scenario(s), dir.string(), o);
}

// The unwrapped position moves as the velocity says (uniform motion: to rounding, relative to
// the 0.35 m gone); the wrapped one stays within the box (but for a last step past a boundary
// before the next neighbour build) and the two differ by whole box lengths.
TEST(PeriodicTracks, UnwrappedPositionsFollowTheMotionThroughAResume) {
  const fs::path whole = fresh_dir("periodic_whole"), parts = fresh_dir("periodic_parts");
  ASSERT_EQ(run(whole), cli::exit_completed);
  ASSERT_EQ(run(parts, 0.17), cli::exit_stopped);
  cli::RunOptions o;
  o.quiet = true;
  ASSERT_EQ(cli::resume_run(parts.string(), o), cli::exit_completed);
  EXPECT_EQ(read_file((whole / "track.csv").string()), read_file((parts / "track.csv").string()));
  const auto tracks = read_tracks((whole / "track.csv").string());
  const std::vector<TrackPoint>& t = tracks.at(0);
  ASSERT_GT(t.size(), 30u);
  for (const TrackPoint& p : t) {
    EXPECT_NEAR(p.unwrapped.x, 0.05 + 1.0 * p.time, 1e-12) << p.time;
    EXPECT_NEAR(p.unwrapped.y, 0.05 + 0.25 * p.time, 1e-12) << p.time;
    EXPECT_GT(p.position.x, -0.01);
    EXPECT_LT(p.position.x, 0.11);
    const double images = (p.unwrapped.x - p.position.x) / 0.1;
    EXPECT_NEAR(images, std::round(images), 1e-9) << p.time;
  }
  EXPECT_NEAR(t.back().unwrapped.x - t.front().unwrapped.x, t.back().time - t.front().time, 1e-12);
  const Checkpoint c = decode_checkpoint(read_file((whole / "checkpoint.bin").string()), "x");
  // at 0.35 s the grain is at x = 0.1 + 2.5e-8 m, y = 0.0375 m: three and one boundaries back
  const Image image = c.state.world.particles.image[0];
  EXPECT_EQ(image.x, 3);
  EXPECT_EQ(image.y, 1);
  fs::remove_all(whole);
  fs::remove_all(parts);
}

// A track.csv written before the unwrapped columns reads its positions as unwrapped.
TEST(PeriodicTracks, ATrackFileWithoutUnwrappedColumnsStillReads) {
  const fs::path dir = fresh_dir("periodic_old_track");
  fs::create_directories(dir);
  write_file_atomically((dir / "track.csv").string(),
                        "time,id,x,y,angle,vx,vy,omega\n0,3,0.01,0.02,0,1,0,0\n");
  const auto tracks = read_tracks((dir / "track.csv").string());
  EXPECT_EQ(tracks.at(3).front().unwrapped, (Vec2{0.01, 0.02}));
  fs::remove_all(dir);
}

} // namespace
} // namespace talus
