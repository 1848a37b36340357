// The observers of the contacts: their events (output.contacts) and the energy ledger.
#include <fmt/core.h>

#include "io/contact_csv.hpp"
#include "run/observers.hpp"

namespace talus::run {

ContactOutput::ContactOutput(RunContext& c) {
  if (!c.book.contact_state.empty()) log_.load(c.book.contact_state);
  // the velocities of the look before: a contact that opens in the next step needs them
  log_.remember(c.sim);
}

void ContactOutput::open(RunContext& c) {
  out_ = &c.files.open("contact_events.csv");
}

void ContactOutput::start(RunContext& c) {
  *out_ << contact_events_header();
  look(c);
}

void ContactOutput::look(RunContext& c) {
  for (const ContactEvent& e : log_.observe(c.sim)) *out_ << contact_event_row(e);
}

void ContactOutput::finish(RunContext&) {
  // the contacts still touching, once: the checkpoint after says the run ended
  for (const ContactEvent& e : log_.open_events()) *out_ << contact_event_row(e);
}

void ContactOutput::changed(RunContext& c, const WorldChange& w) {
  if (w.wall_index.empty()) return;
  for (const ContactEvent& e : log_.renumber_walls(w.wall_index)) *out_ << contact_event_row(e);
  log_.remember(c.sim);
}

LedgerObserver::LedgerObserver(RunContext& c) {
  if (!c.book.ledger_state.empty()) ledger_.load(c.book.ledger_state);
}

void LedgerObserver::changed(RunContext& c, const WorldChange& w) {
  ledger_.changed(contact_powers(c.sim), w.energy_before, energies(c.sim).total());
}

std::string LedgerObserver::thermo_columns(const RunContext& c, const Energies& e) {
  const LedgerRow l = ledger_row(ledger_, e);
  // energy from nowhere: an instability the overlap guard has not seen (yet)
  if (l.growth > ledger_growth_limit)
    throw InstabilityError(energy_growth_diagnosis(c.sim, l, c.book.collision_time));
  return ledger_thermo_columns(l);
}

} // namespace talus::run
