// The run folder the analyses share, the chart helper, and the thermo and forces analyses.
#include "cli/analyze/analyses.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/core.h>

#include "analysis/force_distribution.hpp"
#include "cli/pictures/pictures.hpp"
#include "io/checkpoint.hpp"
#include "io/vtp_reader.hpp"
#include "scenario/file/load.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

extern const char* const plot_script;

RunData::RunData(fs::path dir) : dir_(std::move(dir)), out_(dir_ / "analysis") {
  if (!fs::exists(dir_ / "scenario.toml"))
    throw InvalidArgument("'" + dir_.string() + "' is not a talus run folder (no scenario.toml)");
  scenario_ = load_scenario_file((dir_ / "scenario.toml").string());
}

const fs::path& RunData::out() {
  fs::create_directories(out_);
  return out_;
}

std::vector<Frame> RunData::frames_with_contacts(double from) {
  std::vector<Frame> out;
  for (const Snapshot& s : snapshots_of(dir_))
    if (s.time >= from - 1e-12)
      out.push_back(
          read_vtp_frame(s.particles.string(), s.walls.string(), s.time, s.contacts.string()));
  if (out.empty())
    throw InvalidArgument(fmt::format("--from {}: the run has no snapshots from then on", from));
  return out;
}

bool RunData::has_snapshots() const {
  return fs::exists(dir_ / "particles.pvd");
}

const std::vector<Frame>& RunData::frames(double from) {
  if (all_.empty())
    for (const Snapshot& s : snapshots_of(dir_))
      all_.push_back(read_vtp_frame(s.particles.string(), s.walls.string(), s.time));
  if (all_.front().time >= from - 1e-12) return all_; // every snapshot: no copy
  if (from != picked_from_) {
    picked_.clear();
    for (const Frame& f : all_)
      if (f.time >= from - 1e-12) picked_.push_back(f);
    picked_from_ = from;
    if (picked_.empty())
      throw InvalidArgument(fmt::format("--from {}: the run has no snapshots from then on (the "
                                        "last is at t = {} s)",
                                        from, all_.back().time));
  }
  return picked_;
}

double RunData::mean_radius() {
  const Frame& f = frames(0.0).front();
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < f.radius.size(); ++i)
    if (f.kind[i] == 0) sum += f.radius[i], ++n;
  if (n == 0) throw InvalidArgument(dir_.string() + ": the first snapshot has no free grains");
  return sum / static_cast<double>(n);
}

std::string json_number(double v) {
  return std::isfinite(v) ? fmt::format("{:.6g}", v) : "null";
}

std::string csv_number(double v) {
  return std::isfinite(v) ? fmt::format("{:.6g}", v) : "";
}

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

namespace {
// Whether Debian's python3 has matplotlib, asked once per process: each asking starts Python,
// which costs a good part of what drawing a chart does.
bool matplotlib_available() {
  static const bool available =
      std::system("/usr/bin/python3 -c 'import matplotlib' > /dev/null 2>&1") == 0;
  return available;
}
} // namespace

bool plot(const fs::path& out, const std::string& kind, const fs::path& csv, const fs::path& png,
          const fs::path& json) {
  if (!matplotlib_available()) {
    fmt::print("  (no chart: python3-matplotlib is not installed)\n");
    return false;
  }
  const fs::path script = out / ".plots.py";
  write_file_atomically(script.string(), plot_script);
  const std::string cmd =
      fmt::format("/usr/bin/python3 '{}' {} '{}' '{}' {}", script.string(), kind, csv.string(),
                  png.string(), json.empty() ? std::string() : fmt::format("'{}'", json.string()));
  const bool ok = std::system(cmd.c_str()) == 0;
  fs::remove(script);
  if (!ok) {
    fmt::print(stderr, "talus analyze: the chart {} failed: {}\n", png.string(), cmd);
    ++failed_charts();
  }
  return ok;
}

int& failed_charts() {
  static int failed = 0;
  return failed;
}

Section analyze_thermo(RunData& run) {
  return analyze_thermo(run.dir(), run.out());
}

Section analyze_thermo(const fs::path& dir, const fs::path& out) {
  const fs::path csv = dir / "thermo.csv";
  if (!fs::exists(csv)) throw InvalidArgument(csv.string() + " is missing");
  fs::create_directories(out);
  const fs::path png = out / "thermo.png";
  Section s{"Energies, coordination and packing fraction", {}, {}, {}};
  s.summary = "Kinetic (translation, rotation), elastic and total energy; coordination number Z "
              "and packing fraction against time (thermo.csv).";
  if (plot(out, "thermo", csv, png)) {
    s.charts.push_back(png);
    fmt::print("thermo: energies, coordination and packing fraction against time: {}\n",
               png.string());
  }
  return s;
}

Section analyze_forces(RunData& run, const AnalysisOptions& o) {
  return analyze_forces(run.dir(), run.out(), o);
}

Section analyze_forces(const fs::path& dir, const fs::path& out, const AnalysisOptions& o) {
  if (!fs::exists(dir / "contacts.pvd"))
    throw InvalidArgument("forces: '" + dir.string() +
                          "' has no contacts.pvd (no snapshots, or a run by a talus that wrote "
                          "no contacts in 3D)");
  const auto entries = read_pvd((dir / "contacts.pvd").string());
  if (entries.empty())
    throw InvalidArgument((dir / "contacts.pvd").string() + " lists no snapshots");
  std::vector<std::size_t> picks;
  if (o.frames == "all") {
    for (std::size_t k = 0; k < entries.size(); ++k)
      if (entries[k].first >= o.from - 1e-12) picks.push_back(k);
  } else if (o.frames == "last") {
    picks.push_back(entries.size() - 1);
  } else {
    throw InvalidArgument("--frames '" + o.frames + "': allowed: all, last");
  }
  std::vector<double> scaled; // each snapshot's forces divided by that snapshot's mean
  for (const std::size_t k : picks) {
    std::vector<double> f;
    for (const double v : read_contact_normal_forces((dir / entries[k].second).string()))
      if (v > 0.0) f.push_back(v);
    if (f.empty()) continue;
    double mean = 0.0;
    for (const double v : f) mean += v;
    mean /= static_cast<double>(f.size());
    for (const double v : f) scaled.push_back(v / mean);
  }
  if (scaled.empty())
    throw InvalidArgument("forces: the run's snapshots hold no contact with a normal force");
  const ForceDistribution d = force_distribution(scaled);
  fs::create_directories(out);
  std::string csv = "f_over_mean,probability_density,count\n";
  for (std::size_t k = 0; k < d.centre.size(); ++k)
    csv += fmt::format("{:.4f},{:.6e},{}\n", d.centre[k], d.density[k], d.count[k]);
  write_file_atomically((out / "forces.csv").string(), csv);
  double intercept = 0.0; // of the fitted line through the tail, for the chart
  {
    double sw = 0, sx = 0, sy = 0;
    for (std::size_t k = 0; k < d.centre.size(); ++k)
      if (d.count[k] >= 5 && d.centre[k] >= d.fit_from) {
        const double w = static_cast<double>(d.count[k]);
        sw += w, sx += w * d.centre[k], sy += w * std::log(d.density[k]);
      }
    if (sw > 0) intercept = sy / sw + d.beta * sx / sw;
  }
  const std::string json = fmt::format(
      "{{\"contacts\": {}, \"snapshots\": {}, \"fraction_below_mean\": {:.4f}, \"beta\": {:.4f}, "
      "\"beta_error\": {:.4f}, \"fit_from\": {:.2f}, \"fit_to\": {:.2f}, \"fit_bins\": {}, "
      "\"intercept\": {:.6f}, \"alpha_below_mean\": {:.4f}}}\n",
      d.contacts, picks.size(), d.fraction_below_mean, d.beta, d.beta_error, d.fit_from, d.fit_to,
      d.fit_bins, intercept, d.alpha);
  write_file_atomically((out / "forces.json").string(), json);
  Section s{"Contact force distribution", {}, {}, {}};
  s.summary = "P(f/<f>) of the normal contact forces, each snapshot scaled by its own mean; the "
              "tail above the mean fitted with exp(-beta f/<f>).";
  s.numbers = {
      {"contacts (pooled)", fmt::format("{}", d.contacts)},
      {"snapshots", fmt::format("{}", picks.size())},
      {"share below the mean force", fmt::format("{:.1f} %", 100.0 * d.fraction_below_mean)}};
  fmt::print("forces: {} contacts in {} snapshot(s); {:.1f}% carry less than the mean force\n",
             d.contacts, picks.size(), 100.0 * d.fraction_below_mean);
  if (d.fit_bins >= 3) {
    fmt::print("  exponential tail above the mean: beta = {:.3f} +- {:.3f} (f/<f> from {:.2f} to "
               "{:.2f}, {} bins); below the mean P ~ (f/<f>)^{:.2f}\n",
               d.beta, d.beta_error, d.fit_from, d.fit_to, d.fit_bins, d.alpha);
    s.numbers.emplace_back("beta (tail exp(-beta f/<f>))",
                           fmt::format("{:.3f} +- {:.3f}", d.beta, d.beta_error));
    s.numbers.emplace_back("fitted range", fmt::format("{:.2f} to {:.2f}", d.fit_from, d.fit_to));
  } else {
    fmt::print("  too few contacts above the mean force for a fit\n");
  }
  if (plot(out, "forces", out / "forces.csv", out / "forces.png", out / "forces.json")) {
    fmt::print("  chart: {}\n", (out / "forces.png").string());
    s.charts.push_back(out / "forces.png");
  }
  return s;
}

} // namespace talus::cli
