#pragma once
// `talus run` and `talus resume`: a run (run/run.hpp) in a run folder made and locked here,
// with the signals that stop it at a checkpoint.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "cli/run/run_folder.hpp"
#include "io/checkpoint.hpp"
#include "run/run_book.hpp"
#include "scenario/build.hpp"
#include "scenario/scenario.hpp"

namespace talus::cli {

struct RunOptions {
  int threads = -1;      ///< -1: as the scenario says
  double stop_at = -1.0; ///< s of simulated time: checkpoint and stop there (-1: run to the end)
  bool quiet = false;
  std::vector<std::string> set; ///< resume: "key=value" changes from the resume point on
  double duration = -1.0;       ///< resume: the run's new whole length, s (-1: as it was)
};

/// Exit statuses of a run.
inline constexpr int exit_completed = 0;
inline constexpr int exit_interrupted = 130; ///< stopped by SIGINT/SIGTERM after a checkpoint
inline constexpr int exit_stopped = 4;       ///< stopped by --stop-at after a checkpoint

/// From now on SIGINT and SIGTERM set a flag (stop_signal) instead of ending the process: a
/// run answers them with a checkpoint, a settling by stopping with a word.
void catch_stop_signals();
bool stop_signal();

/// The pictures and the movie the scenario asks for (output.pictures, output.movie), into `dir`.
void scenario_pictures(const Scenario& s, const std::filesystem::path& dir,
                       const run::RunBook& book, bool quiet);

/// A new run's engine and book from a built scenario, with the resolved scenario (its dampers
/// derived for the built grains) written as the folder's scenario.toml. `threads` >= 0 replaces
/// the scenario's simulation.threads.
std::pair<Simulation, run::RunBook> begin_run(const Scenario& s, BuiltScenario built,
                                              const RunFolder& folder, int threads);
/// Starts a new run in a run folder made (and locked) by RunFolder::create.
int start_run(const Scenario& s, BuiltScenario built, RunFolder folder, const RunOptions& o);
/// Starts a new run in `dir` (see RunFolder::create for what dir may hold) from a built scenario.
int start_run(const Scenario& s, BuiltScenario built, const std::string& dir, const RunOptions& o);
/// Builds (settles) `s` in `folder` and starts the run, saying what was built unless quiet;
/// `source` (the scenario as the user named it) prefixes a scenario error, after which the
/// folder is left as it was found.
int settle_and_start(const Scenario& s, RunFolder folder, const RunOptions& o,
                     const std::string& source);
/// The checkpoint a resume of run folder `d` continues from, with its book: the newest that
/// belongs to the folder's run (run::run_id_line; `scenario_text` is its scenario.toml),
/// whose outputs are whole (run::outputs_short_of); the previous one when the newest is not.
/// Throws InvalidArgument with every reason when none is.
std::pair<Checkpoint, run::RunBook> checkpoint_to_resume(const std::filesystem::path& d,
                                                         const std::string& scenario_text);
/// What a resume continues from: the run's scenario now, its engine restored from the last good
/// checkpoint with its book, and the changes the session makes as it starts (edits of
/// scenario.toml, RunOptions::set and duration, checked on a copy), with the outputs cut back to
/// the checkpoint. The folder must hold a checkpoint (never_checkpointed is false).
struct Resumption {
  Scenario scenario;
  Simulation sim;
  run::RunBook book;
  std::vector<std::string> set;
  std::string source;
};
Resumption prepare_resume(const RunFolder& folder, const RunOptions& o);
/// Continues the run in `dir` from its last good checkpoint.
int resume_run(const std::string& dir, const RunOptions& o);

} // namespace talus::cli
