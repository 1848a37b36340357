// The observers that write a row now and then: thermo.csv, track.csv and the progress report.
#include "run/observers.hpp"
#include "run/records.hpp"

namespace talus::run {

ThermoObserver::ThermoObserver(RunContext& c, LedgerObserver* ledger)
    : every_(every_of(c, c.scenario.output.thermo_interval)), ledger_(ledger) {}

void ThermoObserver::open(RunContext& c) {
  out_ = &c.files.open("thermo.csv");
}

void ThermoObserver::start(RunContext& c) {
  std::string head = thermo_header(c.book, ledger_ != nullptr, c.scenario.output);
  if (c.sim.cell_driver() != nullptr) head.insert(head.size() - 1, cell_header());
  *out_ << head;
  record(c);
}

void ThermoObserver::finish(RunContext& c) {
  // the end's state is always recorded, though the interval may not divide the duration
  if (!every_.on(c.sim.step_count())) record(c);
}

void ThermoObserver::record(RunContext& c) {
  const Energies e = energies(c.sim);
  std::string row = thermo_columns(c.sim, c.scenario, c.book, e);
  if (ledger_) row += ledger_->thermo_columns(c, e);
  if (c.scenario.output.stress)
    row += stress_columns(c.sim, stress_region(c.sim, c.scenario, c.book), c.scenario.output);
  *out_ << row << group_force_columns(c.sim, c.book) << cell_columns(c.sim) << "\n";
  c.last_kinetic = e.kinetic();
}

TrackObserver::TrackObserver(RunContext& c)
    : every_{c.sim.clock_step(),
             std::max<std::uint64_t>(
                 1, steps_of(c.scenario.output.track_interval, c.sim.config().timestep))} {}

void TrackObserver::open(RunContext& c) {
  out_ = &c.files.open("track.csv");
}

void TrackObserver::start(RunContext& c) {
  *out_ << "time,id,x,y,angle,vx,vy,omega,xu,yu\n";
  record(c);
}

void TrackObserver::finish(RunContext& c) {
  if (!every_.on(c.sim.step_count())) record(c);
}

void TrackObserver::record(RunContext& c) {
  *out_ << track_rows(c.sim, c.book.tracked);
}

ProgressObserver::ProgressObserver(RunContext& c, RunProgress& progress)
    : every_(every_of(c, c.scenario.output.thermo_interval)), progress_(progress) {}

void ProgressObserver::look(RunContext& c) {
  const std::uint64_t k = c.sim.step_count();
  progress_.report(c.sim.time(), k, c.total_steps, c.stop_step, c.session_wall(), k - c.first_step,
                   c.last_kinetic);
}

} // namespace talus::run
