// `talus analyze DIR [WHAT]`: the thesis' analyses of a run, as CSV files with documented columns
// and charts drawn by matplotlib (Debian's python3-matplotlib).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>

#include <fmt/core.h>

#include "analysis/force_distribution.hpp"
#include "cli/commands.hpp"
#include "core/error.hpp"
#include "io/checkpoint.hpp"
#include "io/vtp_reader.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

// The plotting script, run with Debian's python3 (matplotlib, Agg backend: no display needed).
constexpr const char* plot_script = R"PY(
import csv, json, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

kind, source, target = sys.argv[1], sys.argv[2], sys.argv[3]
rows = list(csv.DictReader(open(source)))
if kind == "thermo":
    t = [float(r["time"]) for r in rows]
    fig, (a, b) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    for key, label in [("kinetic_translational", "kinetic, translation"),
                       ("kinetic_rotational", "kinetic, rotation"), ("elastic", "elastic"),
                       ("total", "total")]:
        a.plot(t, [float(r[key]) for r in rows], label=label)
    a.set_ylabel("energy [J]")
    a.set_yscale("symlog", linthresh=1e-9)
    a.legend(fontsize=8)
    b.plot(t, [float(r["coordination"]) for r in rows], label="coordination number Z")
    b.plot(t, [float(r["packing_fraction"]) for r in rows], label="packing fraction")
    b.set_xlabel("time [s]")
    b.set_ylabel("Z, packing fraction [-]")
    b.legend(fontsize=8)
elif kind == "forces":
    fit = json.load(open(sys.argv[4]))
    x = [float(r["f_over_mean"]) for r in rows if int(r["count"]) > 0]
    p = [float(r["probability_density"]) for r in rows if int(r["count"]) > 0]
    fig, a = plt.subplots(figsize=(7, 5))
    a.semilogy(x, p, "o", ms=4, label=f"{fit['contacts']} contacts")
    if fit["fit_bins"] >= 3:
        import math
        xs = [fit["fit_from"], fit["fit_to"]]
        c = fit["intercept"]
        a.semilogy(xs, [math.exp(c - fit["beta"] * v) for v in xs], "-",
                   label=f"exp(-beta f/<f>), beta = {fit['beta']:.2f} +- {fit['beta_error']:.2f}")
    a.set_xlabel("f / <f> [-]")
    a.set_ylabel("P(f / <f>) [-]")
    a.legend()
fig.tight_layout()
fig.savefig(target, dpi=110)
)PY";

bool plot(const fs::path& dir, const std::string& kind, const fs::path& csv, const fs::path& png,
          const std::string& extra = "") {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' > /dev/null 2>&1") != 0) {
    fmt::print("  (no chart: python3-matplotlib is not installed)\n");
    return false;
  }
  const fs::path script = dir / ".plot.py";
  write_file_atomically(script.string(), plot_script);
  const std::string cmd = fmt::format("/usr/bin/python3 '{}' {} '{}' '{}' {}", script.string(),
                                      kind, csv.string(), png.string(), extra);
  const bool ok = std::system(cmd.c_str()) == 0;
  fs::remove(script);
  if (!ok) fmt::print("  (the chart failed: {})\n", cmd);
  return ok;
}

void analyze_thermo(const fs::path& dir, const fs::path& out) {
  const fs::path csv = dir / "thermo.csv";
  if (!fs::exists(csv)) throw InvalidArgument(csv.string() + " is missing");
  if (plot(out, "thermo", csv, out / "thermo.png"))
    fmt::print("thermo: energies, coordination and packing fraction against time: {}\n",
               (out / "thermo.png").string());
}

void analyze_forces(const fs::path& dir, const fs::path& out, const std::string& frames) {
  const auto entries = read_pvd((dir / "contacts.pvd").string());
  if (entries.empty())
    throw InvalidArgument((dir / "contacts.pvd").string() + " lists no snapshots");
  std::vector<std::size_t> picks;
  if (frames == "all") {
    for (std::size_t k = 0; k < entries.size(); ++k) picks.push_back(k);
  } else if (frames == "last") {
    picks.push_back(entries.size() - 1);
  } else {
    throw InvalidArgument("--frames '" + frames + "': allowed: all, last");
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
  const ForceDistribution d = force_distribution(scaled);
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
  fmt::print("forces: {} contacts in {} snapshot(s); {:.1f}% carry less than the mean force\n",
             d.contacts, picks.size(), 100.0 * d.fraction_below_mean);
  if (d.fit_bins >= 3)
    fmt::print("  exponential tail above the mean: beta = {:.3f} +- {:.3f} (f/<f> from {:.2f} to "
               "{:.2f}, {} bins); below the mean P ~ (f/<f>)^{:.2f}\n",
               d.beta, d.beta_error, d.fit_from, d.fit_to, d.fit_bins, d.alpha);
  else
    fmt::print("  too few contacts above the mean force for a fit\n");
  if (plot(out, "forces", out / "forces.csv", out / "forces.png",
           "'" + (out / "forces.json").string() + "'"))
    fmt::print("  chart: {}\n", (out / "forces.png").string());
}

} // namespace

void add_analyze_command(CLI::App& app) {
  struct Options {
    std::string dir, what = "all", frames = "all";
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "analyze", "analyses of a run folder: thermo (energies, Z, packing fraction against time), "
                 "forces (contact force distribution with its exponential tail); CSV and PNG in "
                 "DIR/analysis");
  cmd->add_option("dir", o->dir, "the run folder")->required()->check(CLI::ExistingDirectory);
  cmd->add_option("what", o->what, "thermo, forces or all")
      ->capture_default_str()
      ->check(CLI::IsMember({"thermo", "forces", "all"}));
  cmd->add_option("--frames", o->frames, "forces: snapshots to pool, all or last")
      ->capture_default_str();
  cmd->callback([o] {
    const fs::path dir(o->dir), out = dir / "analysis";
    fs::create_directories(out);
    if (o->what == "thermo" || o->what == "all") analyze_thermo(dir, out);
    if (o->what == "forces" || o->what == "all") analyze_forces(dir, out, o->frames);
  });
}

} // namespace talus::cli
