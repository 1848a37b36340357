#pragma once
// The events and observers a scenario asks for (run/observer.hpp), in the order they look after
// a step: contacts, the ledger, tracks, thermo, progress, frost, snapshots.
#include <memory>
#include <optional>
#include <ostream>
#include <vector>

#include "analysis/contact_events.hpp"
#include "analysis/energy_ledger.hpp"
#include "frost/frost_front.hpp"
#include "run/observer.hpp"
#include "run/progress.hpp"

namespace talus::run {

/// output.contacts: the contacts looked at after every step, each written to contact_events.csv
/// when it ends (those still touching at the run's end, then).
class ContactOutput final : public Observer {
public:
  explicit ContactOutput(RunContext& c);
  std::uint64_t next_look(std::uint64_t step) const override { return step + 1; }
  void open(RunContext& c) override;
  void start(RunContext& c) override;
  void look(RunContext& c) override;
  void finish(RunContext& c) override;
  void save(RunBook& b) const override { b.contact_state = log_.save(); }
  void changed(RunContext& c, const WorldChange& w) override;

private:
  ContactEventLog log_;
  std::ostream* out_ = nullptr;
};

/// output.energy_ledger: the work of dampers, friction and walls summed after every step; its
/// columns of thermo.csv, and its guard: energy from nowhere stops the run as unstable.
class LedgerObserver final : public Observer {
public:
  explicit LedgerObserver(RunContext& c);
  std::uint64_t next_look(std::uint64_t step) const override { return step + 1; }
  void start(RunContext& c) override { start_ledger(ledger_, c.sim); }
  void look(RunContext& c) override { observe_ledger(ledger_, c.sim); }
  void save(RunBook& b) const override { b.ledger_state = ledger_.save(); }
  void changed(RunContext& c, const WorldChange& w) override;
  /// The ledger's thermo columns at energies `e`; throws InstabilityError when energy grew.
  std::string thermo_columns(const RunContext& c, const Energies& e);

private:
  EnergyLedger ledger_;
};

/// thermo.csv: a row of energies, momenta, contacts and wall forces every output.thermo_interval.
class ThermoObserver final : public Observer {
public:
  ThermoObserver(RunContext& c, LedgerObserver* ledger);
  std::uint64_t next_look(std::uint64_t step) const override { return every_.next(step); }
  void open(RunContext& c) override;
  void start(RunContext& c) override;
  void look(RunContext& c) override { record(c); }
  void finish(RunContext& c) override;

private:
  void record(RunContext& c);
  Every every_;
  LedgerObserver* ledger_;
  std::ostream* out_ = nullptr;
};

/// track.csv: the tracked grains' state every output.track_interval (every step when 0).
class TrackObserver final : public Observer {
public:
  explicit TrackObserver(RunContext& c);
  std::uint64_t next_look(std::uint64_t step) const override { return every_.next(step); }
  void open(RunContext& c) override;
  void start(RunContext& c) override;
  void look(RunContext& c) override { record(c); }
  void finish(RunContext& c) override;

private:
  void record(RunContext& c);
  Every every_;
  std::ostream* out_ = nullptr;
};

/// The progress line or bar, at every thermo row.
class ProgressObserver final : public Observer {
public:
  ProgressObserver(RunContext& c, RunProgress& progress);
  std::uint64_t next_look(std::uint64_t step) const override { return every_.next(step); }
  void look(RunContext& c) override;

private:
  Every every_;
  RunProgress& progress_;
};

/// The snapshots (VTK, and the thesis' run.out with output.thesis_out) every
/// output.snapshot_interval, and the end's when the last is more than half an interval before.
class SnapshotObserver final : public Observer {
public:
  explicit SnapshotObserver(RunContext& c);
  std::uint64_t next_look(std::uint64_t step) const override { return every_.next(step); }
  void open(RunContext& c) override;
  void start(RunContext& c) override;
  void look(RunContext& c) override { write(c); }
  void finish(RunContext& c) override;
  /// The outputs were cut back to the last checkpoint: the collections follow.
  void cut_back(RunContext& c);

private:
  void write(RunContext& c);
  void write_collections(RunContext& c) const;
  Every every_;
  std::ostream* thesis_out_ = nullptr;
};

/// The thesis' uniform freeze (frost.model = "uniform"): at a thermo row with the grains at
/// rest, every free grain heaves (frost/uniform_freeze.hpp); the run ends after frost.cycles.
class UniformFreezeEvent final : public Observer {
public:
  explicit UniformFreezeEvent(RunContext& c);
  std::uint64_t next_look(std::uint64_t step) const override { return thermo_every_.next(step); }
  void open(RunContext& c) override;
  void start(RunContext& c) override;
  void look(RunContext& c) override;

private:
  Every thermo_every_;
  std::ostream* log_ = nullptr;
};

/// The freezing-front model (frost.model = "front"): a freeze starts at a thermo row with the
/// grains at rest; its fronts move on a thousandth of the shorter phase at a time.
class FreezingFrontEvent final : public Observer {
public:
  explicit FreezingFrontEvent(RunContext& c);
  std::uint64_t next_look(std::uint64_t step) const override {
    return std::min(thermo_every_.next(step), front_every_.next(step));
  }
  void open(RunContext& c) override;
  void start(RunContext& c) override;
  void look(RunContext& c) override;
  void save(RunBook& b) const override { b.front_state = front_.save(); }

private:
  Every thermo_every_, front_every_;
  FrostFront front_;
  std::ostream* log_ = nullptr;
};

/// The stages of an experiment ([[stages]]): a stage ends after its duration or, first, when its
/// condition holds at a thermo row; the next starts with its changes. stages.csv gets a row per
/// stage as it ends. A last stage ending on its condition ends the run.
class StageEvent final : public Observer {
public:
  explicit StageEvent(RunContext& c);
  std::uint64_t next_look(std::uint64_t step) const override;
  void open(RunContext& c) override;
  void start(RunContext& c) override;
  void look(RunContext& c) override;
  void finish(RunContext& c) override;

private:
  bool condition_holds(const RunContext& c) const;
  void end_stage(RunContext& c, const char* why);
  void write_row(const RunContext& c, const char* why); ///< stages.csv's row of the stage now
  Every thermo_every_;
  std::ostream* log_ = nullptr;
  const RunContext* c_;
};

/// The observers and events the scenario asks for, in the order they look. `progress` is the
/// run's progress report; the snapshots' observer, if any, is also returned in `snapshots`.
std::vector<std::unique_ptr<Observer>> observers_for(RunContext& c, RunProgress& progress,
                                                     SnapshotObserver*& snapshots);

} // namespace talus::run
