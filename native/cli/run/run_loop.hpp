#pragma once
// A run of a scenario with its run folder: the observers, checkpoints, progress and signals
// that `talus run` and `talus resume` share.
#include <map>
#include <string>
#include <vector>

#include "cli/run_folder.hpp"
#include "scenario/build.hpp"
#include "scenario/scenario.hpp"

namespace talus::cli {

/// The run's own bookkeeping, saved inside every checkpoint.
struct RunBook {
  std::map<std::string, std::uint64_t> file_bytes; ///< output files' sizes at the checkpoint
  std::uint64_t snapshots = 0;                     ///< snapshots written
  std::uint64_t freezes = 0;                       ///< frost: freezes done
  double last_freeze = 0.0;                        ///< s: the last freeze (front: thaw's end)
  std::vector<double> front_state;                 ///< frost front model (FrostFront::save)
  std::vector<double> contact_state; ///< open contacts (ContactEventLog::save), output.contacts
  std::vector<double> ledger_state;  ///< EnergyLedger::save, output.energy_ledger
  double wall_seconds = 0.0;         ///< wall time spent so far
  std::string ended; ///< why the run ended ("duration", "cycles"); empty while it goes on
  double settle_time = 0.0;
  double collision_time = 0.0;
  std::vector<std::uint32_t> tracked;
  std::map<std::string, DriverTargets> groups;
  Rect fill;
  Rect bounds;
  std::string encode() const;
  static RunBook decode(const std::string& text);
};

struct RunOptions {
  int threads = -1;      ///< -1: as the scenario says
  double stop_at = -1.0; ///< s of simulated time: checkpoint and stop there (-1: run to the end)
  bool quiet = false;
};

/// Exit statuses of a run.
inline constexpr int exit_completed = 0;
inline constexpr int exit_interrupted = 130; ///< stopped by SIGINT/SIGTERM after a checkpoint
inline constexpr int exit_stopped = 4;       ///< stopped by --stop-at after a checkpoint

/// Starts a new run in a run folder made (and locked) by RunFolder::create.
int start_run(const Scenario& s, BuiltScenario built, RunFolder folder, const RunOptions& o);
/// Starts a new run in `dir` (see RunFolder::create for what dir may hold) from a built scenario.
int start_run(const Scenario& s, BuiltScenario built, const std::string& dir, const RunOptions& o);
/// Continues the run in `dir` from its last good checkpoint.
int resume_run(const std::string& dir, const RunOptions& o);

} // namespace talus::cli
