// `talus analyze DIR [WHAT]`: the thesis' analyses of a run (cli/analyses.hpp); with no WHAT,
// every analysis that applies, and report.html.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <sstream>

#include <fmt/core.h>

#include "cli/analyze/analyses.hpp"
#include "cli/commands.hpp"
#include "cli/run/run3d.hpp"
#include "cli/run/scenario_source.hpp"
#include "cli/sweep/analyze_sweep.hpp"
#include "cli/sweep/sweep.hpp"
#include "scenario/file/load.hpp"
#include "scenario/geometry.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

// "A,B" with B > A, for --band (m) and --window (s).
std::pair<double, double> parse_pair(const std::string& option, const std::string& text,
                                     const std::string& expected) {
  std::istringstream in(text);
  double a = 0, b = 0;
  char comma = 0;
  if (!(in >> a >> comma >> b) || comma != ',' || !(in >> std::ws).eof() || !(b > a) ||
      !std::isfinite(a) || !std::isfinite(b))
    throw InvalidArgument(option + " '" + text + "': expected " + expected);
  return {a, b};
}

// Below this ratio of the largest to the smallest free grain's radius a bed is taken as of one
// size (a spread of a few tens of percent keeps grains from crystallising; size segregation
// studies use ratios of 1.5 and more).
constexpr double segregation_size_ratio = 1.5;

std::pair<double, double> free_radius_range(const Frame& f) {
  double lo = std::numeric_limits<double>::max(), hi = 0.0;
  for (std::size_t i = 0; i < f.radius.size(); ++i)
    if (f.kind[i] == 0) lo = std::min(lo, f.radius[i]), hi = std::max(hi, f.radius[i]);
  return {lo, hi};
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
    // and of sizes far enough apart for sorting by size to mean something
    const auto [r_small, r_large] = free_radius_range(run.frames(0.0).front());
    if (driven && r_large < segregation_size_ratio * r_small)
      fmt::print("segregation: skipped (the grains' radii span {:.3g} to {:.3g} m, a ratio of "
                 "{:.2f} < {}: too alike to sort by size; `talus analyze DIR segregation` runs it "
                 "anyway)\n",
                 r_small, r_large, r_large / r_small, segregation_size_ratio);
    else if (driven)
      attempt("segregation", [&] { return analyze_segregation(run, o); });
    if (fs::exists(run.dir() / "frost.csv")) attempt("frost", [&] { return analyze_frost(run); });
    // a heap's slope: what rolling resistance is there for (`talus analyze DIR repose` measures
    // any run's)
    if (s.geometry.builder != "silo" &&
        std::any_of(s.materials.begin(), s.materials.end(),
                    [](const Material& m) { return m.rolling_friction > 0.0; }))
      attempt("repose", [&] { return analyze_repose(run); });
    // a packing let down in steps of pressure by servo walls or a cell, its structure recorded
    const bool servo = std::any_of(s.drivers.begin(), s.drivers.end(),
                                   [](const DriverSection& d) { return d.type == "servo"; });
    const bool cell = std::any_of(s.drivers.begin(), s.drivers.end(), [](const DriverSection& d) {
      return d.type == "cell" && d.pressure > 0.0;
    });
    if ((servo || cell) && s.output.stress && s.stages.size() >= 3)
      attempt("jamming", [&] { return analyze_jamming(run, o); });
    // a silo at rest: the wall stress against depth
    if (s.geometry.builder == "silo" && s.geometry.orifice == 0.0 && !driven)
      attempt("janssen", [&] { return analyze_janssen(run, o); });
    // a layer sheared by a sliding servo plate, or a sheared cell: its rheology
    const bool shear = std::any_of(s.drivers.begin(), s.drivers.end(), [](const DriverSection& d) {
      return d.type == "servo" && d.slide_speed != 0.0;
    });
    if ((shear && s.geometry.periodic == "x") || (sheared_cell(s) && s.output.stress))
      attempt("rheology", [&] { return analyze_rheology(run, o); });
    // a layer periodic along a tilted slope: a chute
    if (!servo && s.geometry.periodic == "x" && s.simulation.gravity.x != 0.0)
      attempt("chute", [&] { return analyze_chute(run, o); });
  }
  if (fs::exists(run.dir() / "track.csv")) attempt("tracks", [&] { return analyze_tracks(run); });
  if (fs::exists(run.dir() / "contact_events.csv"))
    attempt("contacts", [&] { return analyze_contacts(run); });
  return out;
}

// A sweep folder: the discharge and its Beverloo fit, or one result of the index; "all" gives
// the discharge where the container has an orifice, and the final state's main numbers.
void analyze_sweep(const fs::path& dir, const std::string& what, const AnalysisOptions& o) {
  if (what == "discharge") return analyze_sweep_discharge(dir, o);
  if (what == "rheology") return analyze_sweep_rheology(dir, o);
  if (what == "chute") return analyze_sweep_chute(dir, o);
  if (what != "all") return analyze_sweep_result(dir, what);
  const SweepPlan plan = read_plan(dir);
  if (plan.runs.empty()) return;
  const fs::path first = dir / "scenarios" / (plan.runs[0].name + ".toml");
  // spheres in 3D have no orifice yet
  if (scenario_dimension(scenario_text(first.string()), {}) == 2 &&
      has_orifice(load_scenario_file(first.string()).geometry))
    analyze_sweep_discharge(dir, o);
  for (const char* r :
       {"final_coordination", "final_packing_fraction", "final_kinetic_translational"}) {
    try {
      analyze_sweep_result(dir, r);
    } catch (const InvalidArgument& e) {
      fmt::print("{}: skipped ({})\n", r, e.what());
    }
  }
}

} // namespace

void check_analysis_name(const std::string& what) {
  const std::vector<std::string> allowed{"thermo",  "forces",   "profiles", "tracks", "segregation",
                                         "frost",   "contacts", "repose",   "fields", "janssen",
                                         "jamming", "rheology", "chute"};
  if (std::find(allowed.begin(), allowed.end(), what) == allowed.end())
    throw InvalidArgument("analyze: '" + what +
                          "' is not an analysis of a run folder; allowed: "
                          "thermo, forces, profiles, tracks, segregation, frost, contacts, "
                          "repose, fields, janssen, jamming, rheology, chute, all");
}

Section analyze_one(RunData& run, const std::string& what, const AnalysisOptions& o) {
  check_analysis_name(what);
  if (what == "thermo") return analyze_thermo(run);
  if (what == "forces") return analyze_forces(run, o);
  if (what == "profiles") return analyze_profiles(run, o);
  if (what == "tracks") return analyze_tracks(run);
  if (what == "contacts") return analyze_contacts(run);
  if (what == "segregation") return analyze_segregation(run, o);
  if (what == "repose") return analyze_repose(run);
  if (what == "fields") return analyze_fields(run, o);
  if (what == "janssen") return analyze_janssen(run, o);
  if (what == "jamming") return analyze_jamming(run, o);
  if (what == "rheology") return analyze_rheology(run, o);
  if (what == "chute") return analyze_chute(run, o);
  return analyze_frost(run);
}

void add_analyze_command(CLI::App& app) {
  struct Options {
    std::string dir, what = "all", band, window;
    AnalysisOptions a;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "analyze",
      "analyses of a run folder, as CSV, JSON and PNG in DIR/analysis: thermo (energies, Z, "
      "packing fraction), forces (contact force distribution), profiles (velocity across a band, "
      "speed map, discharge), tracks, segregation, frost, contacts (contact events), repose (a "
      "heap's angle of repose), fields (coarse-grained density, velocity and stress profiles), "
      "janssen (a silo's wall stress against depth), jamming (the jamming point of a run let down "
      "in steps of pressure), rheology (mu, phi and I of a plane shear flow), chute (a flow down "
      "an incline and "
      "Bagnold's profile); "
      "with no WHAT "
      "every one that applies, "
      "and report.html");
  cmd->add_option("dir", o->dir, "the run folder or sweep folder")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("what", o->what,
                  "thermo, forces, profiles, tracks, segregation, frost, contacts, repose, fields, "
                  "janssen, jamming, rheology, chute, or "
                  "all (with "
                  "report.html); for a sweep folder: discharge (with the Beverloo fit), "
                  "rheology (the mu(I) and phi(I) fits), chute (h_stop), or a "
                  "result of its index.csv")
      ->capture_default_str();
  cmd->add_option("--frames", o->a.frames, "forces: snapshots to pool, all or last")
      ->capture_default_str()
      ->check(CLI::IsMember({"all", "last"}));
  cmd->add_option("--from", o->a.from,
                  "s: leave out snapshots before this time (default: profiles of a flow kept "
                  "going by an orifice, a turning drum or a driven wall leave out the first "
                  "quarter of the run as its start-up; the others nothing)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--band", o->band,
                  "profiles: Y0,Y1 in m (default: just above an orifice, else the middle of the "
                  "bed)");
  cmd->add_option("--window", o->window,
                  "profiles: T0,T1 in s, the discharge window to fit (default: the steady part, "
                  "found from the data)");
  cmd->add_option("--bins", o->a.bins, "profiles, segregation: bins across x (0: automatic)")
      ->capture_default_str()
      ->check(CLI::Range(0, 10000));
  cmd->add_option("--cell", o->a.cell,
                  "profiles: speed map cell in m (0: two mean diameters); fields --map: the map's "
                  "cell (0: the kernel's width)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--axis", o->a.axis,
                  "fields: the profiles' axis, x, y or z (default: y in 2D; in 3D the one gravity "
                  "pulls along, or y without gravity)")
      ->check(CLI::IsMember({"x", "y", "z"}));
  cmd->add_option("--kernel", o->a.kernel, "fields: the coarse-graining kernel")
      ->capture_default_str()
      ->check(CLI::IsMember({"gaussian", "lucy"}));
  cmd->add_flag("--map", o->a.map,
                "fields: maps of the plane (cells of --cell m, default the kernel's width) "
                "instead of profiles along --axis");
  cmd->add_option("--width", o->a.width,
                  "fields: the kernel's width in m, a Gaussian's standard deviation or Lucy's "
                  "cutoff (0: the mean grain radius; Lucy: twice it)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->callback([o] {
    if (!o->band.empty())
      o->a.band = parse_pair("--band", o->band, "Y0,Y1 in m with Y1 > Y0, e.g. 0,0.1");
    if (!o->window.empty())
      o->a.window = parse_pair("--window", o->window, "T0,T1 in s with T1 > T0, e.g. 0.5,2");
    const std::string& w = o->what;
    if (is_sweep_folder(o->dir)) {
      analyze_sweep(o->dir, w, o->a);
      return;
    }
    if (is_3d_run_folder(o->dir)) {
      analyze_3d_run(o->dir, w, o->a);
      return;
    }
    if (w != "all") check_analysis_name(w);
    RunData run{fs::path(o->dir)};
    if (w == "all") {
      const auto sections = analyze_all(run, o->a);
      fmt::print("report: {}\n", write_report(run, sections).string());
    } else {
      analyze_one(run, w, o->a);
    }
    if (failed_charts() > 0) {
      fmt::print(stderr,
                 "talus analyze: {} chart(s) failed (above); the CSV and JSON files stand\n",
                 failed_charts());
      exit_status() = 1;
    }
  });
}

} // namespace talus::cli
