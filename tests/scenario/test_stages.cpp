// Runs in stages ([[stages]]) and runs changed as they go (talus resume --set, --duration).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "cli/run/run_loop.hpp"
#include "cli/run/scenario_edits.hpp"
#include "io/checkpoint.hpp"
#include "run/run_book.hpp"
#include "scenario/file/load.hpp"
#include "support/builtin_scenario.hpp"
#include "support/run_dir.hpp"
#include "support/staged_runs.hpp"

namespace fs = std::filesystem;

namespace talus {
namespace {

using testing::file;
using testing::final_state;
using testing::fresh_dir;
using testing::resume;
using testing::start;

// Forty grains settled in a small box; three stages of 0.01 s each: at rest, tilted with less
// friction, then with Coulomb friction and a finer thermo record, until the run's end.
const char* staged = R"(
name = "staged"
[simulation]
tangential_law = "cundall_strack"
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
snapshot_interval = 0.005
checkpoint_interval = 0.004
picture = false
[[stages]]
name = "rest"
duration = 0.01
[[stages]]
name = "tilt"
duration = 0.01
set = { "simulation.gravity" = [3.0, -9.3], "materials.0.friction" = 0.3 }
[[stages]]
name = "slide"
duration = 0.01
until = "kinetic_below"
kinetic = 1e-300
then = "end"
set = { "simulation.tangential_law" = "coulomb", "output.thermo_interval" = 0.0005 }
)";

// A run in stages stopped inside each stage and resumed lands on exactly the state and the
// records of the run never stopped: each stage's changes are made at the same step, from the
// same state, whether the run goes on or starts again from a checkpoint.
TEST(Stages, AStagedRunStoppedInsideEachStageIsBitIdentical) {
  const Scenario s = load_scenario(staged, "staged.toml");
  ASSERT_EQ(s.stages.size(), 3U);
  EXPECT_DOUBLE_EQ(s.simulation.duration, 0.03); // the stages' sum
  const fs::path whole = fresh_dir("stages_whole"), parts = fresh_dir("stages_parts");
  ASSERT_EQ(start(s, whole), cli::exit_completed);
  ASSERT_EQ(start(s, parts, 0.005), cli::exit_stopped);
  ASSERT_EQ(resume(parts, 0.0151), cli::exit_stopped);
  ASSERT_EQ(resume(parts, 0.0253), cli::exit_stopped);
  ASSERT_EQ(resume(parts), cli::exit_completed);
  EXPECT_EQ(final_state(whole), final_state(parts));
  for (const char* name : {"thermo.csv", "stages.csv", "changes.csv", "particles.pvd"})
    EXPECT_EQ(file(whole / name), file(parts / name)) << name;
  // the stages, one row each, and the changes of the two after the first
  const std::string stages = file(whole / "stages.csv");
  EXPECT_NE(stages.find("0,rest,0,"), std::string::npos) << stages;
  EXPECT_NE(stages.find(",tilt,"), std::string::npos) << stages;
  EXPECT_NE(stages.find(",slide,"), std::string::npos) << stages;
  const std::string changes = file(whole / "changes.csv");
  EXPECT_NE(changes.find("\"stage 1 (tilt)\",\"materials.0.friction=0.3\""), std::string::npos)
      << changes;
  EXPECT_NE(changes.find("\"simulation.tangential_law='coulomb'\""), std::string::npos) << changes;
  // the changes reached the engine
  const Checkpoint c = decode_checkpoint(file(whole / "checkpoint.bin"), "x");
  EXPECT_EQ(c.state.world.gravity, (Vec2{3.0, -9.3}));
  EXPECT_EQ(c.state.world.materials[0].friction, 0.3);
  EXPECT_EQ(c.config.tangential_law, law_id<ViscousCoulomb>);
  fs::remove_all(whole);
  fs::remove_all(parts);
}

// A condition ends its stage at the first thermo row where it holds; with then = "end" it ends
// the run there.
TEST(Stages, AConditionEndsItsStageAndThenEndEndsTheRun) {
  Scenario s = load_scenario(
      staged, "staged.toml",
      {"stages.1.until=\"kinetic_above\"", "stages.1.kinetic=1e-300", "stages.1.then=\"end\""});
  const fs::path dir = fresh_dir("stages_condition");
  ASSERT_EQ(start(s, dir), cli::exit_completed);
  const std::string stages = file(dir / "stages.csv");
  EXPECT_NE(stages.find(",tilt,"), std::string::npos);
  EXPECT_NE(stages.find("kinetic_above"), std::string::npos) << stages;
  EXPECT_EQ(stages.find(",slide,"), std::string::npos) << stages; // never started
  EXPECT_NE(file(dir / "run.json").find("\"ended_by\": \"stages\""), std::string::npos);
  const Checkpoint c = decode_checkpoint(file(dir / "checkpoint.bin"), "x");
  // ended at the first thermo row of the tilt (a step or so after its start at 0.01 s)
  EXPECT_GT(c.state.time, 0.01);
  EXPECT_LT(c.state.time, 0.0115);
  fs::remove_all(dir);
}

// The conditions on the walls and the grains end their stage at the first thermo row where
// they hold: the floor bears the bed's weight, the floor lies below 1 m, all forty grains lie
// below 1 m; and not where they do not (the floor above 1 m, more grains than there are).
TEST(Stages, WallAndGrainConditionsEndTheirStageWhereTheyHold) {
  const std::string two = std::string(staged).substr(0, std::string(staged).find("[[stages]]"));
  const auto ended_by = [&](const std::string& until) {
    const Scenario s = load_scenario(two + "[[stages]]\nduration = 0.004\n" + until +
                                         "\nthen = \"end\"\n[[stages]]\nduration = 0.004\n",
                                     "conditions.toml");
    const fs::path dir = fresh_dir("stages_conditions");
    start(s, dir);
    const std::string stages = file(dir / "stages.csv");
    fs::remove_all(dir);
    return stages.substr(stages.find('\n') + 1);
  };
  for (const std::string until : {"wall_force_above", "wall_position_below", "grains_below"}) {
    const std::string keys = until == "wall_force_above"      ? "group = \"floor\"\nforce = 1e-6"
                             : until == "wall_position_below" ? "group = \"floor\"\nposition = 1"
                                                              : "height = 1.0\ncount = 40";
    const std::string row = ended_by("until = \"" + until + "\"\n" + keys);
    // stage,name,start_time,end_time,ended_by: ended at the first thermo row, 0.001 s
    double start = -1.0, end = -1.0;
    char why[64] = {};
    ASSERT_EQ(std::sscanf(row.c_str(), "0,stage0,%lf,%lf,%63[a-z_]", &start, &end, why), 3) << row;
    EXPECT_EQ(std::string(why), until) << row;
    EXPECT_NEAR(end, 0.001, 1e-5) << row;
    EXPECT_EQ(row.find("stage1"), std::string::npos) << row; // then = "end"
  }
  for (const char* never : {"until = \"wall_position_above\"\ngroup = \"floor\"\nposition = 1.0",
                            "until = \"grains_below\"\nheight = 1.0\ncount = 41"}) {
    const std::string row = ended_by(never);
    EXPECT_NE(row.find("0,stage0,0,0.004"), std::string::npos) << never << ": " << row;
    EXPECT_NE(row.find(",duration\n1,stage1,"), std::string::npos) << never << ": " << row;
  }
  // a group the geometry does not have is refused as the scenario builds
  const Scenario bad = load_scenario(two + "[[stages]]\nduration = 0.004\nuntil = "
                                           "\"wall_force_above\"\ngroup = \"roof\"\nforce = 1\n",
                                     "bad.toml");
  try {
    build_scenario(bad);
    ADD_FAILURE() << "group 'roof' accepted";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("key 'stages.0.group': no wall group 'roof'"),
              std::string::npos)
        << e.what();
  }
}

// A driver changed by a stage starts its new motion from where its targets are: the silo's gate
// slides 0.5 m/s for the "open" stage's 0.1 s and stops, 5 cm along, with no jump; stopped inside
// each stage and resumed, the run is the run never stopped.
TEST(Stages, ADriverChangedByAStageStartsFromWhereItsTargetsAre) {
  const Scenario s = testing::builtin(
      "silo_gate", {"particles.count=60", "stages.0.duration=0.15", "stages.2.count=5",
                    "output.snapshot_interval=0.05", "output.pictures=[]", "output.picture=false"});
  const fs::path whole = fresh_dir("gate_whole"), parts = fresh_dir("gate_parts");
  ASSERT_EQ(start(s, whole), cli::exit_completed);
  ASSERT_EQ(start(s, parts, 0.1), cli::exit_stopped);
  ASSERT_EQ(resume(parts, 0.2), cli::exit_stopped);
  ASSERT_EQ(resume(parts), cli::exit_completed);
  EXPECT_EQ(final_state(whole), final_state(parts));
  EXPECT_EQ(file(whole / "thermo.csv"), file(parts / "thermo.csv"));
  const Checkpoint c = decode_checkpoint(file(whole / "checkpoint.bin"), "x");
  // the gate (the run's group "gate") from x0 = 0.08 m: it moved for the open stage's steps, a
  // duration rounded up to a whole step
  const run::RunBook book = run::RunBook::decode(c.run_data);
  ASSERT_EQ(book.groups.at("gate").segments.size(), 1u);
  const Segment& gate = c.state.world.walls[book.groups.at("gate").segments[0]];
  const double dt = c.config.timestep;
  EXPECT_NEAR(gate.a.x - 0.08, 0.05, 0.5 * dt + 1e-12);
  EXPECT_EQ(gate.velocity, (Vec2{0.0, 0.0}));
  EXPECT_NE(file(whole / "stages.csv").find("2,flow,"), std::string::npos);
  fs::remove_all(whole);
  fs::remove_all(parts);
}

// talus resume --duration runs a finished run on, and --set changes it from the resume point:
// the same, to the bit, as a run whose second stage made that change at that time.
TEST(Stages, ResumeSetAndDurationAreAStageMadeLater) {
  const std::string two = std::string(staged).substr(0, std::string(staged).find("[[stages]]"));
  const Scenario plain = load_scenario(two, "plain.toml", {"simulation.duration=0.01"});
  const Scenario staged_as_resumed = load_scenario(two + R"(
[[stages]]
name = "first"
duration = 0.01
[[stages]]
name = "second"
duration = 0.01
set = { "simulation.gravity" = [1.0, -9.0] }
)",
                                                   "two.toml");
  const fs::path resumed = fresh_dir("stages_resumed"), whole = fresh_dir("stages_two");
  ASSERT_EQ(start(plain, resumed), cli::exit_completed);
  ASSERT_EQ(start(staged_as_resumed, whole), cli::exit_completed);
  ASSERT_EQ(resume(resumed, -1.0, {"simulation.gravity=[1.0,-9.0]"}, 0.02), cli::exit_completed);
  EXPECT_EQ(final_state(whole), final_state(resumed));
  const std::string changes = file(resumed / "changes.csv");
  EXPECT_NE(changes.find("\"resume --set --duration\",\"simulation.gravity=[1.0,-9.0]\""),
            std::string::npos)
      << changes;
  EXPECT_NE(changes.find("simulation.duration=0.02"), std::string::npos) << changes;
  // a resume reads the changes made so far: a further --duration keeps the gravity
  ASSERT_EQ(resume(resumed, -1.0, {}, 0.025), cli::exit_completed);
  const Checkpoint c = decode_checkpoint(file(resumed / "checkpoint.bin"), "x");
  EXPECT_EQ(c.state.world.gravity, (Vec2{1.0, -9.0}));
  EXPECT_NEAR(c.state.time, 0.025, 1e-5);
  fs::remove_all(whole);
  fs::remove_all(resumed);
}

// What cannot be done is refused, naming the key and what is allowed, before the run folder is
// touched: a key a run cannot change, an edited scenario.toml, --set on an ended run without
// --duration, a --duration not beyond the run's time.
TEST(Stages, ChangesThatCannotBeAreRefused) {
  const std::string two = std::string(staged).substr(0, std::string(staged).find("[[stages]]"));
  const Scenario plain = load_scenario(two, "plain.toml", {"simulation.duration=0.005"});
  const fs::path dir = fresh_dir("stages_refused");
  ASSERT_EQ(start(plain, dir), cli::exit_completed);
  const auto refused = [&](std::vector<std::string> set, double duration, const char* words) {
    try {
      resume(dir, -1.0, std::move(set), duration);
      ADD_FAILURE() << "accepted: " << words;
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused({"geometry.width=1"}, 0.01, "'geometry.width' cannot change during a run; allowed:");
  refused({"materials.0.density=1000"}, 0.01, "cannot change during a run");
  refused({"materials.0.friction=-1"}, 0.01, "materials.0.friction");
  refused({"simulation.gravity=[0,-1]"}, -1.0, "has ended (duration)");
  refused({}, 0.004, "the run is at t = ");
  const std::string text = file(dir / "scenario.toml");
  std::string wider = text;
  wider.replace(wider.find("\nwidth = ") + 1, 8, "width = 1.5 # was ");
  write_file_atomically((dir / "scenario.toml").string(), wider);
  refused({}, 0.01,
          "was edited after the run started in keys that cannot change during a run: "
          "geometry.width;");
  fs::rename(cli::started_copy(dir), dir / "kept");
  write_file_atomically((dir / "scenario.toml").string(), text + "# edited\n");
  refused({}, 0.01, "the copy of it as it started is missing");
  fs::rename(dir / "kept", cli::started_copy(dir));
  // a comment is no change: the file is put back as it started, and the run goes on
  EXPECT_EQ(resume(dir, -1.0, {}, 0.01), cli::exit_completed);
  EXPECT_EQ(file(dir / "scenario.toml"), text);
  fs::remove_all(dir);
}

// An edit of scenario.toml in keys a run may change is the change resume --set makes, from the
// resume point, to the bit; changes.csv records it and the file is put back as the run started.
TEST(Stages, AnEditOfChangeableKeysIsAChangeFromTheResumePoint) {
  const std::string two = std::string(staged).substr(0, std::string(staged).find("[[stages]]"));
  const Scenario plain = load_scenario(two, "plain.toml", {"simulation.duration=0.01"});
  const fs::path edited = fresh_dir("stages_edited"), set = fresh_dir("stages_set");
  ASSERT_EQ(start(plain, edited), cli::exit_completed);
  ASSERT_EQ(start(plain, set), cli::exit_completed);
  ASSERT_EQ(resume(set, -1.0, {"simulation.gravity=[1.0,-9.0]"}, 0.02), cli::exit_completed);
  const std::string text = file(edited / "scenario.toml");
  std::string changed = text;
  const auto line = [&](const char* key, const char* value) {
    const std::size_t at = changed.find(std::string("\n") + key + " = ") + 1;
    changed.replace(at, changed.find('\n', at) - at, std::string(key) + " = " + value);
  };
  line("duration", "0.02");
  line("gravity", "[1.0, -9.0]");
  write_file_atomically((edited / "scenario.toml").string(), changed);
  ASSERT_EQ(resume(edited, -1.0, {}, -1.0), cli::exit_completed);
  EXPECT_EQ(final_state(set), final_state(edited));
  EXPECT_EQ(file(edited / "scenario.toml"), text);
  const std::string changes = file(edited / "changes.csv");
  EXPECT_NE(changes.find("\"scenario.toml edited\""), std::string::npos) << changes;
  EXPECT_NE(changes.find("simulation.gravity=[ 1.0, -9.0 ]"), std::string::npos) << changes;
  fs::remove_all(edited);
  fs::remove_all(set);
}

// Bad stages are refused as the scenario loads, naming the stage and the key.
TEST(Stages, BadStagesAreRefusedNamingTheKey) {
  const std::string two = std::string(staged).substr(0, std::string(staged).find("[[stages]]"));
  const auto refused = [&](const std::string& stages, const char* words) {
    try {
      load_scenario(two + stages, "bad.toml");
      ADD_FAILURE() << "accepted: " << stages;
    } catch (const ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused("[[stages]]\nduration = 1\nset = { \"simulation.gravity\" = [1, 0] }\n",
          "the first stage's settings are the scenario's own");
  refused("[[stages]]\n[[stages]]\nduration = 1\n", "key 'stages.0.duration': missing");
  refused("[[stages]]\nduration = 1\n[[stages]]\nduration = 1\nset = { \"geometry.width\" = 1 }\n",
          "'geometry.width' cannot change during a run");
  refused("[[stages]]\nduration = 1\n[[stages]]\nduration = 1\n"
          "set = { \"materials.0.friction\" = -1 }\n",
          "key 'stages.1.set' (stage 'stage1')");
  refused("[[stages]]\nduration = 1\nuntil = \"kinetic_below\"\n",
          "key 'stages.0.kinetic': missing");
  refused("[[stages]]\nduration = 1\nuntil = \"calm\"\n", "key 'stages.0.until'");
  refused("[[stages]]\nduration = 1\nthen = \"end\"\n", "applies only with a condition");
  refused("[[stages]]\nduration = 1\nuntil = \"wall_force_above\"\nforce = 1\n",
          "key 'stages.0.group': missing");
  refused("[[stages]]\nduration = 1\nuntil = \"settled\"\nheight = 1\n",
          "key 'stages.0.height': does not apply to until = \"settled\"");
}

} // namespace
} // namespace talus

namespace talus {
namespace {

// A key changed again and again (a controller's) is loaded once, at its last value, and the
// scenario it gives is the one every change in order gives.
TEST(Stages, AKeyChangedAgainIsLoadedOnceAtItsLastValue) {
  run::RunBook book;
  book.changes.push_back({1, 0.1, "a", {"simulation.gravity=[0, -1]", "materials.0.friction=0.2"}});
  book.changes.push_back({2, 0.2, "b", {"simulation.gravity=[0, -2]"}});
  book.changes.push_back({3, 0.3, "c", {"materials.0.friction=0.4", "simulation.gravity=[1, -3]"}});
  EXPECT_EQ(book.overrides(),
            (std::vector<std::string>{"materials.0.friction=0.4", "simulation.gravity=[1, -3]"}));
  std::vector<std::string> every;
  for (const run::RunChange& c : book.changes)
    every.insert(every.end(), c.set.begin(), c.set.end());
  EXPECT_EQ(to_toml(testing::builtin("tilted_box", every)),
            to_toml(testing::builtin("tilted_box", book.overrides())));
}

} // namespace
} // namespace talus
