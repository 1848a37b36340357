#pragma once
// A 3D run between the engine's steps: thermo rows, snapshots, checkpoints (with the run's book
// of its outputs, so that a resume cuts them back to the checkpoint), run.json, the signals and
// --stop-at. `talus run` starts one (run3d.cpp), `talus resume` continues one.
#include <string>
#include <utility>
#include <vector>

#include "cli/run/run_folder.hpp"
#include "cli/run/run_loop.hpp"
#include "engine3d/simulation3.hpp"
#include "scenario3d/scenario3.hpp"

namespace talus::cli {

/// What a 3D run keeps besides the engine, saved in each checkpoint: its outputs so far.
struct Book3 {
  double collision_time = 0.0;    ///< s
  std::uint64_t thermo_bytes = 0; ///< thermo.csv's length at the checkpoint
  std::vector<std::pair<double, std::string>> spheres, plates; ///< the snapshots (time, file)
  std::vector<double> ledger_state; ///< EnergyLedger::save, with output.energy_ledger

  std::string encode() const;
  /// Throws CheckpointError naming `source` when the text is not a book.
  static Book3 decode(const std::string& text, const std::string& source);
};

/// Runs `sim` in `folder` to simulation.duration (or --stop-at), the outputs appended to what
/// `book` records; returns the exit status. A fresh run passes an empty book.
int run_session3(const Scenario3& s, Simulation3& sim, Book3& book, RunFolder& folder,
                 const RunOptions& o);

/// Continues the 3D run in `folder` from its checkpoint: its outputs cut back to it, the run
/// then bit-identical to one that never stopped.
int resume_3d(RunFolder folder, const RunOptions& o);

} // namespace talus::cli
