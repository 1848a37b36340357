#pragma once
// The run's own bookkeeping, saved inside every checkpoint beside the engine's state: what the
// run's events and observers need to continue exactly where a checkpoint left them.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "scenario/build.hpp"
#include "scenario/scenario.hpp"

namespace talus::run {

/// Changes made to a run as it went: a stage's start, or `talus resume --set/--duration`.
struct RunChange {
  std::uint64_t step = 0;       ///< made after this step
  double time = 0.0;            ///< s
  std::string source;           ///< "stage 1 (tilt)", "resume --set", ...
  std::vector<std::string> set; ///< "key=value" changes, as --set takes them
};

struct RunBook {
  std::map<std::string, std::uint64_t> file_bytes; ///< output files' sizes at the checkpoint
  std::uint64_t snapshots = 0;                     ///< snapshots written
  std::vector<double> snapshot_times;              ///< s: the time of each (older books: none)
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
  /// The wall groups of thermo.csv's force columns, those the run started with: a group a change
  /// took away reads 0 from then on, the walls a change put up count in "walls".
  std::vector<std::string> force_columns;
  Rect fill;
  Rect bounds;
  std::size_t stage = 0;           ///< the stage under way ([[stages]]; = their count: past them)
  std::uint64_t stage_start = 0;   ///< the step it started at
  double stage_start_time = 0.0;   ///< s: the time it started at
  std::vector<RunChange> changes;  ///< in the order they were made
  std::uint64_t scenario_hash = 0; ///< of the run folder's scenario.toml (0: not recorded)
  std::uint64_t run_id = 0;        ///< the run's identity (run_id_line; 0: not recorded)
  /// Every change's "key=value" in order, each key's last setting only: the scenario of the run
  /// now is its folder's scenario.toml with these.
  std::vector<std::string> overrides() const;
  /// The book of a run about to start from a built scenario.
  static RunBook of(const BuiltScenario& built);
  std::string encode() const;
  static RunBook decode(const std::string& text);
};

/// A new run's identity: random, so two runs (of one scenario too) never share it.
std::uint64_t new_run_id();
/// The first line of a run folder's scenario.toml: a comment naming the run, which binds the
/// folder to the checkpoints its run writes.
std::string run_id_line(std::uint64_t id);
/// The run named by a scenario.toml's first line (0: none).
std::uint64_t run_id_in(const std::string& scenario_text);

} // namespace talus::run
