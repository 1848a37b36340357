#include "io/contact_csv.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/observables.hpp"
#include "io/whole_number.hpp"

namespace talus {

std::string contacts_csv(const Simulation& sim) {
  const Particles& p = sim.world().particles;
  std::string out = "time,particle,partner,wall,overlap,normal_force,tangential_force,x,y\n";
  for (const ContactRecord& c : contact_forces(sim)) {
    const bool wall = c.j < 0;
    const std::int64_t partner = wall ? -1 : std::int64_t{p.id[static_cast<std::size_t>(c.j)]};
    out += fmt::format("{},{},{},{},{},{},{},{},{}\n", sim.time(), p.id[c.i], partner,
                       wall ? -1 - c.j : -1, c.overlap, c.normal_force, c.tangential_force,
                       c.point.x, c.point.y);
  }
  return out;
}

std::string contact_events_header() {
  return "particle,partner,wall,start,end,duration,peak_normal_force,peak_overlap,impact_speed,"
         "rebound_speed,touching\n";
}

std::string contact_event_row(const ContactEvent& e) {
  return fmt::format("{},{},{},{},{},{},{},{},{},{},{}\n", e.particle, e.partner, e.wall, e.start,
                     e.end, e.duration(), e.peak_normal_force, e.peak_overlap, e.impact_speed,
                     e.rebound_speed, e.touching ? 1 : 0);
}

std::vector<ContactEvent> read_contact_events(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string line;
  std::getline(in, line);
  if (line + "\n" != contact_events_header())
    throw std::runtime_error(path + ": not a talus contact_events.csv (header '" + line + "')");
  std::vector<ContactEvent> out;
  for (std::size_t number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    std::istringstream row(line);
    double v[11];
    char comma = ',';
    bool ok = static_cast<bool>(row >> v[0]);
    for (int k = 1; k < 11 && ok; ++k) ok = static_cast<bool>(row >> comma >> v[k]) && comma == ',';
    if (!ok || !(row >> std::ws).eof())
      throw std::runtime_error(path + ":" + std::to_string(number) + ": malformed row");
    ContactEvent e;
    const std::string at = path + ":" + std::to_string(number) + ": ";
    e.particle = whole_number<std::uint64_t>(v[0], at + "the particle");
    e.partner = whole_number<std::int64_t>(v[1], at + "the partner");
    e.wall = whole_number<std::int64_t>(v[2], at + "the wall");
    e.start = v[3];
    e.end = v[4]; // v[5] is the duration, end - start
    e.peak_normal_force = v[6];
    e.peak_overlap = v[7];
    e.impact_speed = v[8];
    e.rebound_speed = v[9];
    e.touching = v[10] != 0.0;
    out.push_back(e);
  }
  return out;
}

} // namespace talus
