#pragma once
// The contacts as CSV: a snapshot's touching contacts, and contact events (contact_events.csv).
// Every number is the shortest text that reads back to the engine's double.
#include <string>
#include <vector>

#include "analysis/contact_events.hpp"
#include "simulation/simulation.hpp"

namespace talus {

/// A snapshot's touching contacts, with a header: time, particle and partner ids (partner -1 for
/// a wall), wall (the segment, or -1), overlap (m), normal_force and tangential_force (N), x and
/// y of the contact point (m).
std::string contacts_csv(const Simulation& sim);

/// contact_events.csv's header line, and one event's line.
std::string contact_events_header();
std::string contact_event_row(const ContactEvent& e);
/// A contact_events.csv read back. Throws std::runtime_error naming the file and the line that
/// is malformed; a missing file is an error too.
std::vector<ContactEvent> read_contact_events(const std::string& path);

} // namespace talus
