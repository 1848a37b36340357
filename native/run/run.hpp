#pragma once
// A run of a scenario into its folder: the engine's steps with the events and observers the
// scenario asks for (run/observers.hpp) between them, checkpoints, and the end's records. The
// command line (or any other caller) makes and locks the folder and answers signals.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/checkpoint.hpp"
#include "run/observer.hpp"
#include "run/progress.hpp"
#include "run/run_book.hpp"
#include "run/run_files.hpp"
#include "scenario/scenario.hpp"
#include "simulation/simulation.hpp"
#include "simulation/thread_chooser.hpp"

namespace talus::run {

/// What the caller asks of a run.
struct RunControl {
  double stop_at = -1.0; ///< s of simulated time: checkpoint and stop there (-1: run to the end)
  bool quiet = false;
  std::function<bool()> stop_requested;             ///< true: checkpoint and stop now
  std::function<void(const RunBook&)> end_pictures; ///< after the end: the scenario's pictures
  /// The run's scenario with "key=value" changes (its folder's scenario.toml with them): how a
  /// stage or a resume changes the run. Without it, a change is refused.
  std::function<Scenario(const std::vector<std::string>&)> scenario_with;
  /// Changes made as this session starts (talus resume --set, --duration), with their source.
  std::vector<std::string> set_now;
  std::string set_now_source;
  /// Why the run folder is no longer this run's (deleted, or replaced by another run's), or
  /// empty while it is: checked before the run writes, so it never writes into another folder.
  std::function<std::string()> folder_gone;
};

/// The run folder was deleted or replaced under a running run (RunControl::folder_gone).
class FolderGone : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// How a call of Run::go ended: at the run's end, at RunControl::stop_at (with a checkpoint), at
/// a stop request (with a checkpoint), or at the step the caller paused it at (without one).
enum class RunOutcome { completed, stopped_at, interrupted, paused };

class SnapshotObserver;

class Run {
public:
  /// A run of `s` from `sim` with the bookkeeping `book`: a new run's (`fresh`: its outputs
  /// start empty), or a checkpoint's (they are appended to).
  Run(const Scenario& s, Simulation sim, RunBook book, std::filesystem::path dir, RunControl o,
      bool fresh);
  ~Run();
  /// Opens the outputs and records a new run's start (at the first call), and steps to the end,
  /// to RunControl::stop_at or to a stop request, with a checkpoint there, or to step `pause`
  /// (with every look due there done, and nothing else written): a caller that drives the run in
  /// pieces (the Python module) calls go again to continue, with the same results, bit for bit,
  /// as one call. Throws WriteError with the outputs cut back to the last checkpoint, and
  /// InstabilityError with run.json saying so.
  RunOutcome go(std::uint64_t pause = std::numeric_limits<std::uint64_t>::max());
  /// The run as it stands now: its scenario with the changes made so far, and its book.
  const Scenario& scenario() const { return s_; }
  const RunBook& book() const { return book_; }
  /// Whether the run has ended (and recorded its end); a change of simulation.duration to a
  /// later time lets it go on (as talus resume --duration does).
  bool ended() const { return !book_.ended.empty(); }
  /// An ended run goes on, after a change of simulation.duration to a later time (its end's
  /// records stay as they were written).
  void go_on() { book_.ended.clear(); }
  const Simulation& simulation() const { return sim_; }
  /// Writes a checkpoint of the engine's state and the run's book now (the previous one kept).
  void checkpoint();
  /// Between steps: adds free grains (ParticleSpec; mass and inertia 0: from the scenario's shape
  /// and the material's density) after the checks a scenario's grains get: a finite place and
  /// velocity, a radius > 0, a material of the scenario, no overlap with a grain or a wall, inside
  /// the region the run's grains may be in. Returns their ids; recorded in changes.csv with
  /// `source`, and the energy ledger takes their energy as the change's. Throws ScenarioError
  /// with the run as it was.
  std::vector<std::uint32_t> add_grains(std::vector<ParticleSpec> grains,
                                        const std::string& source);
  /// Between steps: removes the free grains with these ids (their contacts end), as add_grains
  /// records it. Refuses, naming the id, an unknown one, a wall particle and a tracked grain.
  void remove_grains(const std::vector<std::uint32_t>& ids, const std::string& source);
  /// Stops a run paused before its end as RunControl::stop_at does: a checkpoint and run.json
  /// (talus resume continues it). Does nothing to a run that has ended.
  void stop_here();
  /// Writes what the outputs hold in memory to their files (thermo.csv and the others).
  void flush() { files_.flush(); }
  /// Changes the run from this step on: the scenario with every change so far and `set`; what
  /// changed in the engine (gravity, materials, the tangential law, drivers, the timestep,
  /// walls) is applied to it (apply_scenario_change), the events and observers are told
  /// (Observer::changed) and follow the new output intervals. Recorded in the book (saved with
  /// the next checkpoint) and in changes.csv. Throws ScenarioError for a change that cannot be,
  /// with the run as it was.
  void change(const std::vector<std::string>& set, const std::string& source);

private:
  RunOutcome steps(std::uint64_t pause);
  void open();
  void start();
  std::uint64_t steps_to_next_look() const;
  void look_after_step();
  void follow_renumbering();
  void finish(const std::string& why);
  void checkpoint_at(double wall);
  [[noreturn]] void out_of_memory() const;
  void check_folder() const; ///< throws FolderGone when RunControl::folder_gone says why
  [[noreturn]] void stop_on_write_failure(const WriteError& e);
  [[noreturn]] void stop_on_deleted_file(const WriteError& e);
  void write_run_json(double wall, std::uint64_t steps_done, const std::string& ended);
  double wall_now() const;

  /// One row of changes.csv: now, `source` and what changed, each quoted as CSV.
  void log_change(const std::string& source, const std::string& change);
  void record_grain_change(const std::string& what, const std::string& source,
                           double energy_before);
  void make_observers();
  void refresh_observers();
  void set_length();
  void run_stretch(std::uint64_t steps);

  Scenario s_;                   ///< the scenario as it stands now, with the changes made
  bool observers_stale_ = false; ///< a change was made: new observers after this look
  Simulation sim_;
  RunBook book_;
  RunControl o_;
  RunFiles files_;
  RunProgress progress_;
  ThreadChooser threads_;
  RunContext c_;
  std::vector<std::unique_ptr<Observer>> observers_;
  std::vector<std::uint64_t> due_; ///< the step each observer looks at next
  SnapshotObserver* snapshots_ = nullptr;
  std::uint64_t renumberings_seen_ = 0;
  bool opened_ = false;                      ///< go was called: outputs open, start recorded
  std::uint64_t pause_ = 0;                  ///< the step this call of go stops at, unrecorded
  bool checkpointed_ = false;                ///< a checkpoint of this run exists
  std::uint64_t checkpointed_snapshots_ = 0; ///< the snapshots the last checkpoint counts
  double session_wall_before_ = 0.0;         ///< wall seconds of the sessions before this one
  std::chrono::steady_clock::time_point session_start_;
};

} // namespace talus::run
