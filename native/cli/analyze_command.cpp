// `talus analyze DIR [WHAT]`: the thesis' analyses of a run (cli/analyses.hpp); with no WHAT,
// every analysis that applies, and report.html.
#include <filesystem>
#include <memory>
#include <sstream>

#include <fmt/core.h>

#include "cli/analyses.hpp"
#include "cli/commands.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

std::pair<double, double> parse_band(const std::string& text) {
  std::istringstream in(text);
  double y0 = 0, y1 = 0;
  char comma = 0;
  if (!(in >> y0 >> comma >> y1) || comma != ',' || !(in >> std::ws).eof() || !(y1 > y0))
    throw InvalidArgument("--band '" + text + "': expected Y0,Y1 in m with Y1 > Y0, e.g. 0,0.1");
  return {y0, y1};
}

// Every analysis that applies to the run; one that cannot run says why and the others go on.
std::vector<Section> analyze_all(RunData& run, const AnalysisOptions& o) {
  std::vector<Section> out;
  const auto attempt = [&](const char* name, auto&& analysis) {
    try {
      out.push_back(analysis());
    } catch (const InvalidArgument& e) {
      fmt::print("{}: skipped ({})\n", name, e.what());
    }
  };
  attempt("thermo", [&] { return analyze_thermo(run); });
  if (!run.has_snapshots()) {
    fmt::print("no snapshots (output.snapshot_interval = 0): only thermo and tracks apply\n");
  } else {
    attempt("forces", [&] { return analyze_forces(run, o); });
    attempt("profiles", [&] { return analyze_profiles(run, o); });
    const Scenario& s = run.scenario();
    // segregation: grains of mixed sizes driven by shaking or turning
    bool driven = false;
    for (const DriverSection& d : s.drivers) driven = driven || d.type == "vibrate";
    driven = driven || s.geometry.builder == "drum";
    if (driven) attempt("segregation", [&] { return analyze_segregation(run, o); });
    if (fs::exists(run.dir() / "frost.csv")) attempt("frost", [&] { return analyze_frost(run); });
  }
  if (fs::exists(run.dir() / "track.csv")) attempt("tracks", [&] { return analyze_tracks(run); });
  return out;
}

} // namespace

void add_analyze_command(CLI::App& app) {
  struct Options {
    std::string dir, what = "all", band;
    AnalysisOptions a;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "analyze",
      "analyses of a run folder, as CSV, JSON and PNG in DIR/analysis: thermo (energies, Z, "
      "packing fraction), forces (contact force distribution), profiles (velocity across a band, "
      "speed map, discharge), tracks, segregation, frost; with no WHAT every one that applies, "
      "and report.html");
  cmd->add_option("dir", o->dir, "the run folder")->required()->check(CLI::ExistingDirectory);
  cmd->add_option("what", o->what,
                  "thermo, forces, profiles, tracks, segregation, frost, or all (with report.html)")
      ->capture_default_str()
      ->check(
          CLI::IsMember({"thermo", "forces", "profiles", "tracks", "segregation", "frost", "all"}));
  cmd->add_option("--frames", o->a.frames, "forces: snapshots to pool, all or last")
      ->capture_default_str()
      ->check(CLI::IsMember({"all", "last"}));
  cmd->add_option("--from", o->a.from, "s: leave out snapshots before this time")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--band", o->band,
                  "profiles: Y0,Y1 in m (default: just above an orifice, else the middle of the "
                  "bed)");
  cmd->add_option("--bins", o->a.bins, "profiles, segregation: bins across x (0: automatic)")
      ->capture_default_str()
      ->check(CLI::Range(0, 10000));
  cmd->add_option("--cell", o->a.cell, "profiles: speed map cell in m (0: two mean diameters)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->callback([o] {
    if (!o->band.empty()) o->a.band = parse_band(o->band);
    RunData run{fs::path(o->dir)};
    const std::string& w = o->what;
    if (w == "all") {
      const auto sections = analyze_all(run, o->a);
      fmt::print("report: {}\n", write_report(run, sections).string());
    } else if (w == "thermo") {
      analyze_thermo(run);
    } else if (w == "forces") {
      analyze_forces(run, o->a);
    } else if (w == "profiles") {
      analyze_profiles(run, o->a);
    } else if (w == "tracks") {
      analyze_tracks(run);
    } else if (w == "segregation") {
      analyze_segregation(run, o->a);
    } else {
      analyze_frost(run);
    }
  });
}

} // namespace talus::cli
