// Runs of the built-in scenarios (shortened), resume after a stop, files a reader can open.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <functional>

#include "cli/run/run_loop.hpp"
#include "io/checkpoint.hpp"
#include "io/contact_csv.hpp"
#include "io/thesis_format.hpp"
#include "io/track_csv.hpp"
#include "io/vtp_reader.hpp"
#include "scenario/file/load.hpp"
#include "support/builtin_scenario.hpp"
#include "support/run_dir.hpp"
#include "support/run_scenario.hpp"

namespace fs = std::filesystem;

namespace talus {
namespace {

using testing::fresh_dir;

using testing::builtin;

int run(const Scenario& s, const fs::path& dir, double stop_at = -1.0) {
  return testing::run_quietly(s, dir, stop_at);
}

// Each built-in scenario builds and runs a few milliseconds with fewer grains.
class BuiltinScenario : public ::testing::TestWithParam<std::string> {};

TEST_P(BuiltinScenario, BuildsAndRunsShortened) {
  const std::string name = GetParam();
  std::vector<std::string> set = {"simulation.duration=0.004", "output.snapshot_interval=0.002",
                                  "packing.settle_max_time=0.02"};
  if (name != "collisions") set.push_back("particles.count=120");
  if (name == "collisions") set.push_back("output.thesis_out=true");
  const Scenario s = builtin(name, set);
  const fs::path dir = fresh_dir(name);
  ASSERT_EQ(run(s, dir), cli::exit_completed);
  for (const char* f : {"scenario.toml", "thermo.csv", "run.json", "particles.pvd",
                        "checkpoint.bin", "snapshots/particles_000000.vtp"})
    EXPECT_TRUE(fs::exists(dir / f)) << name << ": " << f;
  // run.json says which step the scene got (step_features.hpp): what it leaves out
  const std::string json = read_file((dir / "run.json").string());
  EXPECT_NE(json.find("\"step\": \""), std::string::npos) << json;
  if (name == "collisions") { // four disks of one material, no walls, no gravity
    EXPECT_NE(json.find("history-free, no walls, no drivers, one material, no gravity"),
              std::string::npos)
        << json;
  }
  if (name == "collisions") { // the thesis' .out format: its 5-line header, then 13 columns
    const std::string out = read_file((dir / "run.out").string());
    EXPECT_EQ(out.substr(0, out.find('\n')), "4");
    const ThesisFile back = read_thesis_in(out, "run.out", After::more_blocks); // the first block
    EXPECT_EQ(back.particles.size(), 4U);
    EXPECT_DOUBLE_EQ(back.particles[0].vx, 0.01);
  }
  // the resolved scenario reruns: it loads back to the same scenario
  const Scenario again = load_scenario_file((dir / "scenario.toml").string());
  EXPECT_EQ(to_toml(again), to_toml(s));
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(All, BuiltinScenario,
                         ::testing::Values("collisions", "hourglass", "silo_shake", "force_network",
                                           "frost_heave", "drum", "frost_front"));

// The grains' positions, velocities, spins and springs at the folder's last checkpoint.
std::string motion_state(const fs::path& dir) {
  const Checkpoint c = decode_checkpoint(read_file((dir / "checkpoint.bin").string()), "x");
  const Particles& p = c.state.world.particles;
  std::string bytes(reinterpret_cast<const char*>(p.position.data()),
                    p.position.size() * sizeof(Vec2));
  bytes.append(reinterpret_cast<const char*>(p.velocity.data()), p.velocity.size() * sizeof(Vec2));
  bytes.append(reinterpret_cast<const char*>(p.angular_velocity.data()), p.size() * sizeof(double));
  bytes.append(reinterpret_cast<const char*>(c.state.neighbours.history.data()),
               c.state.neighbours.history.size() * sizeof(double));
  return bytes;
}

// Stop halfway (with a checkpoint), resume, and land on exactly the uninterrupted result.
TEST(Resume, IsBitIdenticalToAnUninterruptedRun) {
  for (const std::string integrator : {"gear", "verlet"}) {
    const Scenario s =
        builtin("drum", {"particles.count=150", "packing.settle_max_time=0.05",
                         "simulation.duration=0.03", "output.checkpoint_interval=0.007",
                         "output.snapshot_interval=0.005", "simulation.integrator=" + integrator});
    const fs::path whole = fresh_dir("whole"), parts = fresh_dir("parts");
    ASSERT_EQ(run(s, whole), cli::exit_completed);
    ASSERT_EQ(run(s, parts, 0.0123), cli::exit_stopped);
    cli::RunOptions o;
    o.quiet = true;
    o.threads = 2; // a different thread count on resume changes nothing
    ASSERT_EQ(cli::resume_run(parts.string(), o), cli::exit_completed);
    EXPECT_EQ(motion_state(whole), motion_state(parts)) << integrator;
    EXPECT_EQ(read_file((whole / "thermo.csv").string()),
              read_file((parts / "thermo.csv").string()));
    EXPECT_EQ(read_file((whole / "particles.pvd").string()),
              read_file((parts / "particles.pvd").string()));
    fs::remove_all(whole);
    fs::remove_all(parts);
  }
}

// The frost front's state (columns, fronts, heave, frozen grains, the ice under stones and the
// ice content) is in the checkpoint: a run stopped in the middle of a freeze or of a thaw
// continues exactly.
TEST(Resume, FrostFrontMidFreezeOrThawIsBitIdentical) {
  const Scenario s = builtin(
      "frost_front",
      {"particles.count=150", "packing.settle_max_time=0.05", "simulation.duration=0.2",
       "frost.kinetic_threshold=1e3", "frost.min_interval=0.01", "frost.freeze_time=0.04",
       "frost.thaw_time=0.04", "frost.heave_strain=0.05", "output.checkpoint_interval=0.05"});
  const fs::path whole = fresh_dir("frost_whole");
  ASSERT_EQ(run(s, whole), cli::exit_completed);
  const std::string events = read_file((whole / "frost.csv").string());
  EXPECT_NE(events.find("thawed"), std::string::npos) << events;
  // the freeze runs from 0.01 to 0.05 s, the thaw to 0.17 s (the front reaches the frozen layer's
  // bottom at 0.09 s; the ice under the stones takes the rest)
  for (const double stop : {0.03, 0.07}) {
    const fs::path parts = fresh_dir("frost_parts");
    ASSERT_EQ(run(s, parts, stop), cli::exit_stopped);
    cli::RunOptions o;
    o.quiet = true;
    ASSERT_EQ(cli::resume_run(parts.string(), o), cli::exit_completed);
    EXPECT_EQ(motion_state(whole), motion_state(parts)) << "stopped at " << stop << " s";
    EXPECT_EQ(events, read_file((parts / "frost.csv").string()));
    fs::remove_all(parts);
  }
  fs::remove_all(whole);
}

TEST(Resume, ACorruptCheckpointFallsBackToThePreviousOne) {
  const Scenario s =
      builtin("collisions", {"simulation.duration=0.02", "output.checkpoint_interval=0.004"});
  const fs::path dir = fresh_dir("corrupt");
  ASSERT_EQ(run(s, dir, 0.01), cli::exit_stopped);
  // damage the latest checkpoint: flip a byte in the middle
  std::string bytes = read_file((dir / "checkpoint.bin").string());
  bytes[bytes.size() / 2] ^= 0x5A;
  write_file_atomically((dir / "checkpoint.bin").string(), bytes);
  EXPECT_THROW(decode_checkpoint(bytes, "damaged"), CheckpointError);
  cli::RunOptions o;
  o.quiet = true;
  EXPECT_EQ(cli::resume_run(dir.string(), o), cli::exit_completed);
  fs::remove_all(dir);
}

TEST(Resume, TruncatedCheckpointIsDetected) {
  const Scenario s = builtin("collisions", {"simulation.duration=0.002"});
  const fs::path dir = fresh_dir("truncated");
  ASSERT_EQ(run(s, dir), cli::exit_completed);
  const std::string bytes = read_file((dir / "checkpoint.bin").string());
  EXPECT_THROW(decode_checkpoint(bytes.substr(0, bytes.size() - 9), "cut"), CheckpointError);
  EXPECT_THROW(decode_checkpoint("not a checkpoint", "text"), CheckpointError);
  fs::remove_all(dir);
}

// A checkpoint a talus of an earlier format wrote (tests/data/README.md says how each was made),
// of format `version`.
Checkpoint old_checkpoint(const char* name, std::uint32_t version) {
  const std::string file = std::string(TALUS_SOURCE_DIR) + "/tests/data/" + name;
  const std::string bytes = read_file(file);
  std::uint32_t written = 0;
  std::memcpy(&written, bytes.data() + 8, sizeof(written));
  EXPECT_EQ(written, version) << name;
  return decode_checkpoint(bytes, file);
}

// The old checkpoint holds the very state this talus reaches on the same run, and restores.
void expect_the_state_of(const Checkpoint& old, const Scenario& s, const char* dir_name) {
  const fs::path dir = fresh_dir(dir_name);
  ASSERT_EQ(run(s, dir), cli::exit_completed);
  const Checkpoint now = decode_checkpoint(read_file((dir / "checkpoint.bin").string()), "now");
  EXPECT_EQ(old.state.steps, now.state.steps);
  EXPECT_EQ(encode_checkpoint({old.state, old.config, ""}),
            encode_checkpoint({now.state, now.config, ""}));
  EXPECT_NO_THROW(Simulation::restore(old.state, old.config));
  fs::remove_all(dir);
}

// Format 8 changed only the checksum's basis and dropped the padding bytes of three structs.
TEST(Resume, AFormat7CheckpointIsReadToTheSameState) {
  expect_the_state_of(old_checkpoint("collisions-format7.ckpt", 7),
                      builtin("collisions", {"simulation.duration=0.002"}), "format7");
}

// A checkpoint of format 8, with a driver (the grain press' lid): format 9 added only the
// driver's start time, 0 for every driver of format 8.
TEST(Resume, AFormat8CheckpointIsReadToTheSameState) {
  const Checkpoint old = old_checkpoint("force_network-format8.ckpt", 8);
  ASSERT_EQ(old.state.world.drivers.size(), 1u);
  EXPECT_EQ(old.state.world.drivers[0].start_time, 0.0);
  expect_the_state_of(old,
                      builtin("force_network", {"particles.count=20", "simulation.duration=0.002"}),
                      "format8");
}

// Format 9 had no image counts: they read as none crossed.
TEST(Resume, AFormat9CheckpointIsReadToTheSameState) {
  const Checkpoint old = old_checkpoint("drum-format9.ckpt", 9);
  EXPECT_EQ(old.state.world.particles.image.size(), old.state.world.particles.size());
  expect_the_state_of(old,
                      builtin("drum", {"particles.count=20", "simulation.duration=0.002",
                                       "packing.settle_max_time=0.01"}),
                      "format9");
}

// Format 10 had no rolling resistance: the materials read with none, the list with no rolling
// springs.
TEST(Resume, AFormat10CheckpointIsReadToTheSameState) {
  const Checkpoint old = old_checkpoint("drum-format10.ckpt", 10);
  for (const Material& m : old.state.world.materials) EXPECT_EQ(m.rolling_friction, 0.0);
  EXPECT_TRUE(old.state.neighbours.rolling.empty());
  expect_the_state_of(old,
                      builtin("drum", {"particles.count=20", "simulation.duration=0.002",
                                       "packing.settle_max_time=0.01"}),
                      "format10");
}

// A checkpoint whose checksum holds but whose arrays disagree in length (written by a defective
// build, say) is refused when read, whichever per-particle field is off: read on, the short
// array would be indexed beyond its end.
TEST(Resume, ArraysOfDifferentLengthsAreRefused) {
  const Scenario s = builtin("collisions", {"simulation.duration=0.002"});
  const fs::path dir = fresh_dir("lengths");
  ASSERT_EQ(run(s, dir), cli::exit_completed);
  const Checkpoint good = decode_checkpoint(read_file((dir / "checkpoint.bin").string()), "c");
  std::size_t fields = 0;
  good.state.world.particles.for_each_field([&](const auto& v) { fields += !v.empty(); });
  for (std::size_t k = 0; k < fields; ++k) {
    Checkpoint bad = good;
    std::size_t seen = 0;
    bad.state.world.particles.for_each_field([&](auto& v) {
      if (!v.empty() && seen++ == k) v.pop_back();
    });
    EXPECT_THROW(decode_checkpoint(encode_checkpoint(bad), "bad"), CheckpointError)
        << "field " << k << " one short";
  }
  EXPECT_GE(fields, 20u); // the state's 14 fields and Gear's six derivatives
  fs::remove_all(dir);
}

// A count of records (materials, drivers) that could not fit in what is left of the file is
// refused before anything is allocated for it: a damaged count once asked for 2^60 materials and
// ended the program with std::length_error (found by fuzz_checkpoint).
TEST(Resume, ACountBeyondTheFileIsRefused) {
  std::size_t fields = 0;
  Particles{}.for_each_field([&](const auto&) { ++fields; });
  std::string payload((fields + 1) * sizeof(std::uint64_t), '\0'); // no particles, no walls
  const std::uint64_t materials = std::uint64_t{1} << 60;
  payload.append(reinterpret_cast<const char*>(&materials), sizeof(materials));
  try {
    decode_checkpoint(seal_checkpoint(payload), "counted");
    ADD_FAILURE() << "no error";
  } catch (const CheckpointError& e) {
    EXPECT_NE(std::string(e.what()).find("a count of records runs past the end"), std::string::npos)
        << e.what();
  }
}

// A saved state whose checksum holds but whose neighbour list or drivers do not fit its
// particles and walls (a defective writer) is refused by Simulation::restore, before a step
// indexes it: the force stage and the drivers read those arrays without checks. One scene with
// segment walls turned by a driver (the drum), one with driven wall particles (the shaken silo).
TEST(Resume, AListOrDriverThatDoesNotFitIsRefused) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> scenes{
      {"drum", {"particles.count=40", "packing.settle_max_time=0.05", "simulation.duration=0.001"}},
      {"silo_shake",
       {"particles.count=40", "packing.settle_max_time=0.05", "simulation.duration=0.001",
        "geometry.walls=particles"}}};
  for (const auto& [name, sets] : scenes) {
    const fs::path dir = fresh_dir("misfit_" + name);
    ASSERT_EQ(run(builtin(name, sets), dir), cli::exit_completed);
    const Checkpoint good = decode_checkpoint(read_file((dir / "checkpoint.bin").string()), "c");
    EXPECT_NO_THROW(Simulation::restore(good.state, good.config)) << name;
    const std::size_t n = good.state.world.particles.size();
    const std::vector<std::pair<std::string, std::function<void(SimulationState&)>>> damage{
        {"a neighbour beyond the particles",
         [&](SimulationState& s) { s.neighbours.neighbour.at(0) = static_cast<std::uint32_t>(n); }},
        {"row offsets past the entries",
         [](SimulationState& s) { ++s.neighbours.row_offset.back(); }},
        {"an image short", [](SimulationState& s) { s.neighbours.image.pop_back(); }},
        {"a spring short", [](SimulationState& s) { s.neighbours.history.pop_back(); }},
        {"a driver's origin short", [](SimulationState& s) {
           Driver& d = s.world.drivers.at(0);
           if (!d.segment_origin.empty())
             d.segment_origin.pop_back();
           else
             d.particle_origin.pop_back();
         }}};
    for (const auto& [what, change] : damage) {
      SimulationState bad = good.state;
      change(bad);
      EXPECT_THROW(Simulation::restore(bad, good.config), InvalidArgument) << name << ": " << what;
    }
    fs::remove_all(dir);
  }
}

// track.select = "all" follows every grain at full precision (the last track point is the final
// state, bit for bit), and the end of a run is a snapshot even where the interval does not
// divide the duration (unless one falls within half an interval of it).
TEST(RunOutputs, EveryGrainTrackedExactlyAndTheEndIsASnapshot) {
  const fs::path dir = fresh_dir("track_all");
  const Scenario s = builtin("collisions", {"track.select=all", "output.snapshot_interval=0.08"});
  ASSERT_EQ(run(s, dir), cli::exit_completed);
  const auto tracks = read_tracks((dir / "track.csv").string());
  ASSERT_EQ(tracks.size(), 4u);
  const Checkpoint c = decode_checkpoint(read_file((dir / "checkpoint.bin").string()), "c");
  const Particles& p = c.state.world.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const TrackPoint& last = tracks.at(p.id[i]).back();
    EXPECT_EQ(last.position.x, p.position[i].x) << "id " << p.id[i];
    EXPECT_EQ(last.velocity.y, p.velocity[i].y) << "id " << p.id[i];
  }
  // snapshots at 0 and 0.08 s, and the end at 0.15 s
  EXPECT_TRUE(fs::exists(dir / "snapshots/particles_000002.vtp"));
  EXPECT_FALSE(fs::exists(dir / "snapshots/particles_000003.vtp"));
  // the collection gives each its own time: the end's is the last track point's (the pvd's 9
  // digits), not two intervals' 0.16 s
  const auto entries = read_pvd((dir / "particles.pvd").string());
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_NEAR(entries[1].first, 0.08, 1e-3);
  EXPECT_NEAR(entries[2].first, tracks.at(0).back().time, 1e-8 * entries[2].first);
  EXPECT_NEAR(entries[2].first, 0.15, 1e-3);
}

// A snapshot's ids, kinds and materials are whole numbers; one that is not, or does not fit its
// type (a damaged or edited file), is refused naming the file, the array and the entry: converting
// it would be undefined. (A word that is no number, "nan" say, ends the array's numbers there:
// "arrays of different lengths".)
TEST(RunOutputs, ASnapshotWithAnIdThatIsNotOneIsRefused) {
  const fs::path dir = fresh_dir("snapshot_ids");
  ASSERT_EQ(run(builtin("collisions", {"simulation.duration=0.002"}), dir), cli::exit_completed);
  const std::string file = (dir / "snapshots/particles_000000.vtp").string();
  const std::string good = read_file(file);
  EXPECT_NO_THROW(read_vtp_frame(file, "", 0.0));
  const std::vector<std::pair<std::string, std::string>> damage{{"Name=\"id\"", "-1"},
                                                                {"Name=\"id\"", "1e30"},

                                                                {"Name=\"kind\"", "2.5"},
                                                                {"Name=\"material\"", "70000"}};
  for (const auto& [array, value] : damage) {
    std::string bad = good;
    const std::size_t first = bad.find('\n', bad.find(array)) + 1; // the array's first number
    bad.replace(first, bad.find('\n', first) - first, value);
    write_file_atomically(file, bad);
    try {
      read_vtp_frame(file, "", 0.0);
      ADD_FAILURE() << array << " " << value << " accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(file + ": DataArray '"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("' at entry 0 holds " +
                                           std::to_string(std::stod(value)) +
                                           "; allowed: whole numbers 0 to"),
                std::string::npos)
          << e.what();
    }
  }
  fs::remove_all(dir);
}

// The same for the ids of track.csv and contact_events.csv, with the file's line.
TEST(RunOutputs, ATrackOrContactEventIdThatIsNotOneIsRefused) {
  const fs::path dir = fresh_dir("csv_ids");
  fs::create_directories(dir);
  const std::string track = (dir / "track.csv").string();
  const std::string header = "time,id,x,y,angle,vx,vy,omega\n";
  write_file_atomically(track, header + "0,0,0,0,0,0,0,0\n0,4294967296,0,0,0,0,0,0\n");
  try {
    read_tracks(track);
    ADD_FAILURE() << "an id of 2^32 accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(track + ":3: the id holds 4294967296.000000; allowed: "
                                                 "whole numbers 0 to 4294967295"),
              std::string::npos)
        << e.what();
  }
  write_file_atomically(track, header + "0,7,0,0,0,0,0,0\n");
  EXPECT_EQ(read_tracks(track).count(7), 1u);
  const std::string events = (dir / "contact_events.csv").string();
  const std::string row = "0,-1,0.5,0,1,1,1,1,1,1,0\n"; // a wall of index one half
  write_file_atomically(events, contact_events_header() + row);
  try {
    read_contact_events(events);
    ADD_FAILURE() << "a wall of index 0.5 accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(events + ":2: the wall holds 0.500000"), std::string::npos)
        << e.what();
  }
  write_file_atomically(events, contact_events_header() + "0,-1,3,0,1,1,1,1,1,1,0\n");
  EXPECT_EQ(read_contact_events(events).at(0).wall, 3);
  fs::remove_all(dir);
}

TEST(RunFolder, NothingIsWrittenWhenTheScenarioIsBad) {
  const fs::path dir = fresh_dir("bad");
  EXPECT_THROW(
      {
        const Scenario s = load_scenario("[particles]\ncount = 100000\n[geometry]\nbuilder = "
                                         "\"box\"\nwidth = 0.1\nheight = 0.1\n",
                                         "bad.toml");
        run(s, dir);
      },
      ScenarioError);
  EXPECT_FALSE(fs::exists(dir));
}

TEST(ThesisFormat, InFileRoundTripsThroughAScenario) {
  const std::string in = "3\n1\n0.5\n1e-06\n0 -9.81 0\n"
                         "0.01 0.02 0 0.1 0 0 0.001 0.002 0 0.5 0.01 10000 50\n"
                         "0.02 0.02 0 -0.1 0 0 0.001 0.002 0 0.5 0.01 10000 50\n"
                         "0.0 0.0 0 0 0 0 0.001 0.002 1 0.5 0.01 10000 50\n";
  const ThesisFile f = read_thesis_in(in, "a.in");
  ASSERT_EQ(f.particles.size(), 3U);
  const Scenario s = scenario_from_thesis(f, "a");
  EXPECT_EQ(s.simulation.normal_law, law_id<LinearSpringDashpot>);
  EXPECT_DOUBLE_EQ(s.materials[0].normal_stiffness, 10000.0);
  EXPECT_EQ(s.particles.list[2].kind, "fixed");
  const Scenario reread = load_scenario(to_toml(s), "a.toml");
  EXPECT_EQ(write_thesis_in(thesis_from_scenario(reread)), write_thesis_in(f));
}

TEST(ThesisFormat, BadLinesNameTheLineAndColumn) {
  try {
    read_thesis_in("1\n1\n0.5\n1e-6\n0 -9.81 0\n0.01 0.02 0 0.1 0 0 0.001\n", "b.in");
    FAIL();
  } catch (const ScenarioError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("b.in:6"), std::string::npos) << what;
    EXPECT_NE(what.find("column 8 (radius)"), std::string::npos) << what;
  }
  EXPECT_THROW(read_thesis_in("1\n7\n", "c.in"), ScenarioError);
}

// More particle lines than N, or a 14th column, would silently drop or misread a particle.
TEST(ThesisFormat, SurplusLinesAndColumnsAreRefused) {
  const std::string head = "1\n1\n0.5\n1e-06\n0 -9.81 0\n";
  const std::string grain = "0.01 0.02 0 0.1 0 0 0.001 0.002 0 0.5 0.01 10000 50";
  const auto refusal = [](const std::string& text) {
    try {
      read_thesis_in(text, "d.in");
    } catch (const ScenarioError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_NE(
      refusal(head + grain + "\n" + grain + "\n").find("d.in:7: a particle line beyond the N = 1"),
      std::string::npos);
  EXPECT_NE(refusal(head + grain + " 7\n").find("d.in:6: particle line: more than 13 columns"),
            std::string::npos);
  EXPECT_EQ(refusal(head + grain + "\n\n  \n"), "(accepted)"); // trailing blank lines are fine
}

} // namespace
} // namespace talus
