#pragma once
// The run layer's one interface. Everything a run does between the engine's steps is an event
// (it changes the simulation: a freeze, a front) or an observer (it records: thermo, tracks,
// snapshots, contacts, the ledger, progress). Each says when it next looks, what it does then,
// what it records at the run's start and end, and what it keeps in a checkpoint.
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "run/run_book.hpp"
#include "run/run_files.hpp"
#include "scenario/scenario.hpp"
#include "simulation/simulation.hpp"

namespace talus::run {

/// A step no run reaches: an observer that never looks again.
inline constexpr std::uint64_t never = std::numeric_limits<std::uint64_t>::max();

/// The steps of an interval of `interval` s at a timestep `dt` (s), at least 1; 0 for an interval
/// of 0 (off). An interval beyond any run is cut to a count no run reaches.
std::uint64_t steps_of(double interval, double dt);

/// The first multiple of `every` after `step` (`never` when every is 0).
inline std::uint64_t next_multiple(std::uint64_t step, std::uint64_t every) {
  return every == 0 ? never : (step / every + 1) * every;
}

/// A look every `steps` steps counted from `origin`, the step the timestep in force started at
/// (Simulation::clock_step): an interval's steps change with the timestep, and count from there.
struct Every {
  std::uint64_t origin = 0;
  std::uint64_t steps = 0; ///< 0: never
  /// The first step of the grid after `step` (`never` when steps is 0).
  std::uint64_t next(std::uint64_t step) const {
    return steps == 0 ? never : origin + next_multiple(step - origin, steps);
  }
  /// Whether `step` is on the grid.
  bool on(std::uint64_t step) const { return steps != 0 && (step - origin) % steps == 0; }
  /// How far `step` is past the grid's last step before it.
  std::uint64_t past(std::uint64_t step) const { return steps == 0 ? 0 : (step - origin) % steps; }
};

struct RunContext;
/// An interval of `interval` s as a grid of steps at the timestep in force, from its start.
Every every_of(const RunContext& c, double interval);

/// What a change (Run::change) did, for the events and observers whose state follows the world.
struct WorldChange {
  double energy_before = 0.0;           ///< J: the total energy just before, of the same state
  std::vector<std::int64_t> wall_index; ///< each old wall's new index (-1: removed); empty: none
};

/// What the events and observers of one run share.
struct RunContext {
  RunContext(const Scenario& s, Simulation& sim_, RunBook& book_, RunFiles& files_)
      : scenario(s), sim(sim_), book(book_), files(files_) {}
  const Scenario& scenario;
  Simulation& sim;
  RunBook& book;
  RunFiles& files;
  bool quiet = false;
  bool progress_on_terminal = false;    ///< a progress bar is drawn: no lines of news between
  std::uint64_t total_steps = 0;        ///< the run's whole length in steps
  std::uint64_t stop_step = 0;          ///< where this session stops (the end, or --stop-at)
  std::uint64_t first_step = 0;         ///< the step this session began at
  std::function<double()> session_wall; ///< wall seconds this session has taken so far
  double last_kinetic = 0.0;            ///< J: the kinetic energy at the last thermo row
  std::string end; ///< set by an event that ends the run ("cycles"); empty otherwise
  /// Changes the run from now on: "key=value" changes as --set takes them, recorded with their
  /// source (Run::change). The events and observers after the caller look at the changed run.
  std::function<void(const std::vector<std::string>&, const std::string&)> change;
};

class Observer {
public:
  virtual ~Observer() = default;
  /// The first step after `step` at which it looks (`never`: it does not).
  virtual std::uint64_t next_look(std::uint64_t step) const = 0;
  /// Opens its files: a new run's start empty, a resumed run's are appended to.
  virtual void open(RunContext&) {}
  /// A new run, at its first step: headers and the first record.
  virtual void start(RunContext&) {}
  /// After a step it asked for. An event may end the run by setting RunContext::end.
  virtual void look(RunContext&) = 0;
  /// The run has ended (RunBook::ended says why): the end's record, where the last look missed it.
  virtual void finish(RunContext&) {}
  /// Its state into the checkpoint's book (restored by its constructor from the book it gets).
  virtual void save(RunBook&) const {}
  /// The run was changed after this step's looks (or as a session starts): what its state must
  /// follow (the observers are made again from their saved state after it).
  virtual void changed(RunContext&, const WorldChange&) {}
};

} // namespace talus::run
