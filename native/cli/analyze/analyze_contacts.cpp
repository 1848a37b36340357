// `talus analyze DIR contacts`: the contact events of a run (output.contacts), summarised per
// kind of contact (grain-grain, grain-wall), with charts of their durations, peak forces and
// restitutions against the impact speed.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include <fmt/core.h>

#include "cli/analyze/analyses.hpp"
#include "io/checkpoint.hpp"
#include "io/contact_csv.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double mean(const std::vector<double>& v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (const double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

double largest(const std::vector<double>& v) {
  return v.empty() ? std::numeric_limits<double>::quiet_NaN()
                   : *std::max_element(v.begin(), v.end());
}

double smallest(const std::vector<double>& v) {
  return v.empty() ? std::numeric_limits<double>::quiet_NaN()
                   : *std::min_element(v.begin(), v.end());
}

// The events of one kind: the ended ones' durations and peaks, and the restitution of those
// that came in and went out (a contact there from the start, or still touching, has neither).
struct KindSummary {
  std::string kind;
  std::size_t events = 0, touching = 0;
  std::vector<double> duration, peak_force, peak_overlap, restitution;
};

KindSummary summarise(const std::vector<ContactEvent>& events, bool walls) {
  KindSummary k{walls ? "wall" : "pair", 0, 0, {}, {}, {}, {}};
  for (const ContactEvent& e : events) {
    if ((e.wall >= 0) != walls) continue;
    ++k.events;
    if (e.touching) {
      ++k.touching;
      continue;
    }
    k.duration.push_back(e.duration());
    k.peak_force.push_back(e.peak_normal_force);
    k.peak_overlap.push_back(e.peak_overlap);
    if (e.impact_speed > 0.0 && e.rebound_speed > 0.0)
      k.restitution.push_back(e.rebound_speed / e.impact_speed);
  }
  return k;
}

} // namespace

Section analyze_contacts(RunData& run) {
  const fs::path file = run.dir() / "contact_events.csv";
  if (!fs::exists(file))
    throw InvalidArgument(
        "'" + run.dir().string() +
        "' has no contact_events.csv: set output.contacts = true in the scenario");
  const std::vector<ContactEvent> events = read_contact_events(file.string());
  const fs::path out = run.out();
  std::string csv = "kind,events,touching,duration_mean,duration_median,duration_min,duration_max,"
                    "peak_normal_force_mean,peak_normal_force_max,peak_overlap_max,"
                    "restitution_median,restitution_count\n";
  std::string json = fmt::format("{{\"events\": {}, \"kinds\": [", events.size());
  Section s{"Contact events", {}, {}, {}};
  s.summary = fmt::format(
      "{} contacts from contact_events.csv: each contact's duration, peak normal force and peak "
      "overlap, and its restitution (separation over approach speed) where it both came in and "
      "went out during the run.",
      events.size());
  fmt::print("contacts: {} events\n", events.size());
  for (const bool walls : {false, true}) {
    const KindSummary k = summarise(events, walls);
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}\n", k.kind, k.events, k.touching,
                       csv_number(mean(k.duration)), csv_number(median(k.duration)),
                       csv_number(smallest(k.duration)), csv_number(largest(k.duration)),
                       csv_number(mean(k.peak_force)), csv_number(largest(k.peak_force)),
                       csv_number(largest(k.peak_overlap)), csv_number(median(k.restitution)),
                       k.restitution.size());
    json += fmt::format("{}{{\"kind\": \"{}\", \"events\": {}, \"touching\": {}, "
                        "\"duration_median\": {}, \"peak_normal_force_max\": {}, "
                        "\"peak_overlap_max\": {}, \"restitution_median\": {}}}",
                        walls ? ", " : "", k.kind, k.events, k.touching,
                        json_number(median(k.duration)), json_number(largest(k.peak_force)),
                        json_number(largest(k.peak_overlap)), json_number(median(k.restitution)));
    if (k.events == 0) continue;
    const std::string what = walls ? "grain-wall" : "grain-grain";
    s.numbers.emplace_back(what + " contacts (still touching at the end)",
                           fmt::format("{} ({})", k.events, k.touching));
    s.numbers.emplace_back(what + " duration, median (min to max)",
                           fmt::format("{:.4g} s ({:.4g} to {:.4g} s)", median(k.duration),
                                       smallest(k.duration), largest(k.duration)));
    s.numbers.emplace_back(what + " peak normal force, largest",
                           fmt::format("{:.4g} N", largest(k.peak_force)));
    if (!k.restitution.empty())
      s.numbers.emplace_back(
          what + " restitution, median",
          fmt::format("{:.4f} ({} impacts)", median(k.restitution), k.restitution.size()));
    fmt::print("  {}: {} contacts, {} still touching; duration median {:.4g} s; peak force up to "
               "{:.4g} N\n",
               what, k.events, k.touching, median(k.duration), largest(k.peak_force));
  }
  write_file_atomically((out / "contacts.csv").string(), csv);
  write_file_atomically((out / "contacts.json").string(), json + "]}\n");
  if (plot(out, "contacts", file, out / "contacts.png")) {
    s.charts.push_back(out / "contacts.png");
    fmt::print("  chart: {}\n", (out / "contacts.png").string());
  }
  return s;
}

} // namespace talus::cli
