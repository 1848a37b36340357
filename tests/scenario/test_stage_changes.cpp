// Changes of a run that the engine's steps and the run's records must follow: the timestep, and
// walls removed (an orifice opened) or added during a run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include <fmt/core.h>

#include "cli/run/run_loop.hpp"
#include "io/checkpoint.hpp"
#include "io/contact_csv.hpp"
#include "run/run_book.hpp"
#include "scenario/file/load.hpp"
#include "support/run_dir.hpp"
#include "support/staged_runs.hpp"
#include "support/thermo_rows.hpp"

namespace fs = std::filesystem;

namespace talus {
namespace {

using testing::file;
using testing::final_state;
using testing::fresh_dir;
using testing::resume;
using testing::start;

Checkpoint last_checkpoint(const fs::path& dir) {
  return decode_checkpoint(file(dir / "checkpoint.bin"), "x");
}

// The end time of stage `name` in stages.csv (stage,name,start_time,end_time,ended_by).
double stage_end(const std::string& csv, const std::string& name) {
  const std::size_t at = csv.find("," + name + ",");
  if (at == std::string::npos) return -1.0;
  const std::size_t start = at + name.size() + 2;
  return std::stod(csv.substr(csv.find(',', start) + 1));
}

// The first column of every row of a CSV file after its header.
std::vector<double> times_of(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<double> out;
  while (std::getline(in, line)) out.push_back(std::stod(line.substr(0, line.find(','))));
  return out;
}

// Forty grains settled in a small box, then on with a timestep a third as long.
const char* finer = R"(
name = "finer"
[particles]
count = 40
size = { mean_radius = 0.003 }
[packing]
method = "sedimentation"
settle_max_time = 0.05
[geometry]
builder = "box"
width = 0.05
height = 0.05
[output]
thermo_interval = 0.001
snapshot_interval = 0.004
checkpoint_interval = 0.003
picture = false
energy_ledger = true
[[stages]]
name = "coarse"
duration = 0.0101
[[stages]]
name = "fine"
duration = 0.01
set = { "simulation.timestep_factor" = 150, "simulation.gravity" = [2.0, -9.81] }
)";

// A stage that changes the timestep: the steps after it are a third as long, their times count
// from the change, the records keep their intervals in seconds, and the run stopped inside each
// stage and resumed is the run never stopped, to the bit.
TEST(StageChanges, ATimestepChangedByAStageCountsTimeFromTheChange) {
  const Scenario s = load_scenario(finer, "finer.toml");
  const double dt0 = build_scenario(s).config.timestep;
  const fs::path whole = fresh_dir("dt_whole"), parts = fresh_dir("dt_parts");
  ASSERT_EQ(start(s, whole), cli::exit_completed);
  ASSERT_EQ(start(s, parts, 0.005), cli::exit_stopped);
  ASSERT_EQ(resume(parts, 0.0152), cli::exit_stopped);
  ASSERT_EQ(resume(parts), cli::exit_completed);
  EXPECT_EQ(final_state(whole), final_state(parts));
  for (const char* name : {"thermo.csv", "stages.csv", "changes.csv", "particles.pvd"})
    EXPECT_EQ(file(whole / name), file(parts / name)) << name;
  const Checkpoint c = last_checkpoint(whole);
  EXPECT_NEAR(c.config.timestep, dt0 / 3.0, 1e-12 * dt0); // the default factor is 50
  // the change came at the first step at or past 0.0101 s, and the run ends at 0.0201 s
  const std::uint64_t change = static_cast<std::uint64_t>(std::ceil(0.0101 / dt0 - 1e-9));
  EXPECT_EQ(c.state.clock_step, change);
  EXPECT_DOUBLE_EQ(c.state.clock_time, static_cast<double>(change) * dt0);
  EXPECT_EQ(c.state.time,
            c.state.clock_time + static_cast<double>(c.state.steps - change) * c.config.timestep);
  EXPECT_NEAR(c.state.time, 0.0201, c.config.timestep); // the stages' sum
  // thermo rows every 0.001 s: on the first timestep's grid, then on the new one from the change
  const std::vector<double> t = times_of(file(whole / "thermo.csv"));
  for (std::size_t k = 1; k + 1 < t.size(); ++k) {
    const bool after = t[k - 1] >= c.state.clock_time;
    if (after) {
      EXPECT_NEAR(t[k] - t[k - 1], 0.001, 0.5 * c.config.timestep) << k;
    } else if (t[k] < c.state.clock_time) {
      EXPECT_NEAR(t[k] - t[k - 1], 0.001, 0.5 * dt0) << k;
    }
  }
  // the ledger takes the gravity's change as the change's, not as energy from nowhere
  // (its terms here are of 1e-7 J, the gravity's change of 0.1 J)
  EXPECT_LT(std::abs(testing::last_thermo_row(whole)["energy_imbalance"]), 1e-10);
  // the snapshots' times in the collection are those they were taken at: the first after the
  // change an interval after it, on the new timestep's grid
  const std::string pvd = file(whole / "particles.pvd");
  std::vector<double> shots;
  for (std::size_t at = pvd.find("timestep=\""); at != std::string::npos;
       at = pvd.find("timestep=\"", at + 1))
    shots.push_back(std::stod(pvd.substr(at + 10)));
  const auto first_after =
      std::find_if(shots.begin(), shots.end(), [&](double x) { return x > c.state.clock_time; });
  ASSERT_NE(first_after, shots.end());
  EXPECT_NEAR(*first_after - c.state.clock_time, 0.004, 0.5 * c.config.timestep);
  fs::remove_all(whole);
  fs::remove_all(parts);
}

// One grain falling freely: Gear's predictor-corrector is exact for a constant acceleration, so
// across a change of the timestep (resume --set) the grain is where y0 - g t^2 / 2 says, to
// rounding: the integrator's derivatives need no rescaling and the clock no correction.
TEST(StageChanges, AFreeFallAcrossATimestepChangeIsExact) {
  const Scenario s = load_scenario(R"(
name = "fall"
[simulation]
timestep = 2e-5
duration = 0.05
[particles]
list = [ { position = [0.0, 1.0], radius = 0.01 } ]
[geometry]
builder = "none"
[output]
thermo_interval = 0.01
snapshot_interval = 0
picture = false
)",
                                   "fall.toml");
  const fs::path dir = fresh_dir("dt_fall");
  ASSERT_EQ(start(s, dir, 0.02), cli::exit_stopped);
  ASSERT_EQ(resume(dir, -1.0, {"simulation.timestep=7e-6"}), cli::exit_completed);
  const Checkpoint c = last_checkpoint(dir);
  EXPECT_EQ(c.config.timestep, 7e-6);
  EXPECT_EQ(c.state.clock_step, 1000u);
  const double t = c.state.time;
  EXPECT_NEAR(t, 0.05, 7e-6);
  const Particles& p = c.state.world.particles;
  // rounding of about a thousand steps at a few ulps of 1 m
  EXPECT_NEAR(p.position[0].y, 1.0 - 0.5 * 9.81 * t * t, 1e-12);
  EXPECT_NEAR(p.velocity[0].y, -9.81 * t, 1e-12);
  EXPECT_NE(file(dir / "changes.csv").find("simulation.timestep=7e-6"), std::string::npos);
  fs::remove_all(dir);
}

// A silo filled onto a gate that is then taken away (geometry.gate = false): the gate's walls
// leave the world and its group the run, the grains on it fall through the orifice, their
// contacts with it end where it went, the ledger balances, and the run stopped inside each
// stage and resumed is the run never stopped.
const char* gate_removed = R"(
name = "gate_removed"
[simulation]
normal_law = "linear"
tangential_law = "cundall_strack"
[[materials]]
name = "pebble"
normal_stiffness = 1.0e5
restitution = 0.5
friction = 0.5
[particles]
count = 60
material = "pebble"
size = { distribution = "uniform", mean_radius = 0.004, spread = 0.0008 }
[geometry]
builder = "silo"
width = 0.1
height = 0.2
orifice = 0.03
gate = true
wall_material = "pebble"
[output]
thermo_interval = 0.01
snapshot_interval = 0.05
checkpoint_interval = 0.1
picture = false
contacts = true
energy_ledger = true
[[stages]]
name = "fill"
duration = 0.3
until = "settled"
[[stages]]
name = "open"
duration = 0.5
until = "grains_below"
height = 0.0
count = 10
set = { "geometry.gate" = false }
)";

TEST(StageChanges, AGateRemovedOpensTheOrifice) {
  const Scenario s = load_scenario(gate_removed, "gate_removed.toml");
  const BuiltScenario built = build_scenario(s);
  const std::size_t walls = built.world.walls.size();
  ASSERT_EQ(built.groups.at("gate").segments.size(), 1u);
  const fs::path whole = fresh_dir("gate_removed_whole"), parts = fresh_dir("gate_removed_parts");
  ASSERT_EQ(start(s, whole), cli::exit_completed);
  const std::string stages = file(whole / "stages.csv");
  ASSERT_NE(stages.find(",open,"), std::string::npos) << stages;
  EXPECT_NE(stages.find("grains_below"), std::string::npos) << stages;
  const Checkpoint c = last_checkpoint(whole);
  EXPECT_EQ(c.state.world.walls.size(), walls - 1);
  const run::RunBook book = run::RunBook::decode(c.run_data);
  EXPECT_EQ(book.groups.count("gate"), 0u);
  EXPECT_EQ(book.groups.at("walls").segments.size(), walls - 1);
  for (const std::uint32_t k : book.groups.at("floor").segments) EXPECT_LT(k, walls - 1);
  // contacts with the gate (its index at the build) ended where it went, at the fill's end
  const double fill_end = stage_end(stages, "fill");
  const std::uint32_t gate = built.groups.at("gate").segments[0];
  std::size_t ended_there = 0;
  for (const ContactEvent& e : read_contact_events((whole / "contact_events.csv").string()))
    if (e.wall == gate && std::abs(e.end - fill_end) < 1e-8) ++ended_there; // 9 digits
  EXPECT_GT(ended_there, 0u);
  // the ledger takes the springs the gate took away as the change's: the imbalance stays small
  EXPECT_LT(std::abs(testing::last_thermo_row(whole)["energy_imbalance"]), 1e-6);
  // stopped in each stage (the change at the fill's end) and resumed: the same run
  ASSERT_EQ(start(s, parts, 0.5 * fill_end), cli::exit_stopped);
  ASSERT_EQ(resume(parts, fill_end + 0.02), cli::exit_stopped);
  ASSERT_EQ(resume(parts), cli::exit_completed);
  EXPECT_EQ(final_state(whole), final_state(parts));
  for (const char* name : {"thermo.csv", "stages.csv", "changes.csv", "contact_events.csv"})
    EXPECT_EQ(file(whole / name), file(parts / name)) << name;
  fs::remove_all(whole);
  fs::remove_all(parts);
}

// A gate put back (geometry.gate = true) before the grains reach the orifice closes it: no grain
// falls through.
TEST(StageChanges, AGatePutBackClosesTheOrifice) {
  std::string text = gate_removed;
  text.replace(text.find("gate = true"), 11, "gate = false");
  text = text.substr(0, text.find("[[stages]]")) + R"(
[[stages]]
name = "open"
duration = 0.001
[[stages]]
name = "closed"
duration = 0.3
set = { "geometry.gate" = true }
)";
  const Scenario s = load_scenario(text, "gate_back.toml");
  const BuiltScenario built = build_scenario(s);
  ASSERT_EQ(built.groups.count("gate"), 0u);
  const fs::path dir = fresh_dir("gate_back");
  ASSERT_EQ(start(s, dir), cli::exit_completed);
  const Checkpoint c = last_checkpoint(dir);
  EXPECT_EQ(c.state.world.walls.size(), built.world.walls.size() + 1);
  const run::RunBook book = run::RunBook::decode(c.run_data);
  ASSERT_EQ(book.groups.at("gate").segments.size(), 1u);
  const Segment& gate = c.state.world.walls[book.groups.at("gate").segments[0]];
  EXPECT_EQ(gate.a.y, 0.0);
  const Particles& p = c.state.world.particles;
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_GT(p.position[i].y, 0.0) << i;
  fs::remove_all(dir);
}

// A lid put up during a run (geometry.segments) holds the grains when gravity turns upward: they
// gather under it. Taken away again, the grains go on up to the box's lid.
TEST(StageChanges, AWallAddedDuringARunHoldsTheGrains) {
  const std::string box = std::string(finer).substr(0, std::string(finer).find("[[stages]]"));
  const Scenario s = load_scenario(box + R"(
[[stages]]
name = "rest"
duration = 0.01
[[stages]]
name = "lid"
duration = 0.15
set = { "geometry.segments" = [ { a = [0.0, 0.045], b = [0.05, 0.045] } ], "simulation.gravity" = [0.0, 9.81] }
)",
                                   "lid.toml");
  const std::size_t walls = build_scenario(s).world.walls.size();
  const fs::path dir = fresh_dir("lid_added");
  ASSERT_EQ(start(s, dir), cli::exit_completed);
  const Checkpoint c = last_checkpoint(dir);
  ASSERT_EQ(c.state.world.walls.size(), walls + 1);
  const run::RunBook book = run::RunBook::decode(c.run_data);
  ASSERT_EQ(book.groups.at("extra").segments, std::vector<std::uint32_t>{std::uint32_t(walls)});
  EXPECT_EQ(book.groups.at("walls").segments.size(), walls + 1);
  const Particles& p = c.state.world.particles;
  double top = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) top = std::max(top, p.position[i].y + p.radius[i]);
  // the highest grain rests against the lid, pressed into it by a small share of a radius
  EXPECT_GT(top, 0.045);
  EXPECT_LT(top, 0.045 + 0.1 * 0.003);
  // the lid taken away (resume --set): the grains rise to the box's own lid at 0.05 m
  ASSERT_EQ(resume(dir, -1.0, {"geometry.segments=[]"}, 0.25), cli::exit_completed);
  const Checkpoint after = last_checkpoint(dir);
  EXPECT_EQ(after.state.world.walls.size(), walls);
  EXPECT_EQ(run::RunBook::decode(after.run_data).groups.count("extra"), 0u);
  const Particles& q = after.state.world.particles;
  top = 0.0;
  for (std::size_t i = 0; i < q.size(); ++i) top = std::max(top, q.position[i].y + q.radius[i]);
  EXPECT_GT(top, 0.05);
  EXPECT_LT(top, 0.05 + 0.1 * 0.003);
  fs::remove_all(dir);
}

// Changes of walls and of the timestep that cannot be made are refused before the run folder
// is touched, naming the key: a wall across a grain, a timestep past the stability bound, a
// driven gate taken away, walls made of particles.
TEST(StageChanges, WallAndTimestepChangesThatCannotBeAreRefused) {
  const std::string box = std::string(finer).substr(0, std::string(finer).find("[[stages]]"));
  const auto refused = [](const fs::path& dir, const std::string& set, const char* words) {
    const std::string before = file(dir / "thermo.csv");
    try {
      resume(dir, -1.0, {set}, 1.0);
      ADD_FAILURE() << "accepted: " << set;
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
    EXPECT_EQ(file(dir / "thermo.csv"), before) << set;
  };
  const fs::path dir = fresh_dir("changes_refused");
  ASSERT_EQ(start(load_scenario(box, "box.toml", {"simulation.duration=0.002"}), dir),
            cli::exit_completed);
  refused(dir, "geometry.segments=[{a=[0.0,0.003],b=[0.05,0.003]}]",
          "key 'geometry.segments': the wall added from (0, 0.003) to (0.05, 0.003) m cuts into "
          "grain");
  refused(dir, "simulation.timestep=1", "key 'simulation.timestep': 1 s is above the stability");
  fs::remove_all(dir);
  ASSERT_EQ(start(load_scenario(box, "box.toml",
                                {"simulation.duration=0.002", "geometry.walls=\"particles\""}),
                  dir),
            cli::exit_completed);
  refused(dir, "geometry.segments=[{a=[0.0,0.045],b=[0.05,0.045]}]",
          "walls made of particles (geometry.walls = \"particles\") cannot be added or removed");
  fs::remove_all(dir);
  Scenario silo = load_scenario(gate_removed, "silo.toml", {"simulation.duration=0.002"});
  silo.stages.clear();
  DriverSection d;
  d.type = "translate";
  d.target = "gate";
  silo.drivers.push_back(d);
  ASSERT_EQ(start(silo, dir), cli::exit_completed);
  refused(dir, "geometry.gate=false", "the group 'gate', which a driver (translate) moves");
  fs::remove_all(dir);
}

} // namespace
} // namespace talus
