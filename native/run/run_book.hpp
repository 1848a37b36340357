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
  /// The book of a run about to start from a built scenario.
  static RunBook of(const BuiltScenario& built);
  std::string encode() const;
  static RunBook decode(const std::string& text);
};

} // namespace talus::run
