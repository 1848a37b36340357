// `talus analyze SWEEP rheology`: each run's plane shear flow (mu, phi, I), and the friction and
// dilatancy laws fitted over them (post/rheology.hpp).
#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "cli/analyze/analyses.hpp"
#include "cli/run/run3d.hpp"
#include "cli/sweep/analyze_sweep.hpp"
#include "cli/sweep/sweep.hpp"
#include "io/checkpoint.hpp"
#include "post/rheology.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace talus::cli {

namespace {

json line_json(const LineFit& f) {
  if (!f.ok) return {{"ok", false}, {"why_not", f.why_not}};
  return {
      {"ok", true},        {"intercept", f.intercept},     {"intercept_error", f.intercept_error},
      {"slope", f.slope},  {"slope_error", f.slope_error}, {"rms", f.rms},
      {"points", f.points}};
}

json mu_json(const MuIFit& f) {
  if (!f.ok) return {{"ok", false}, {"why_not", f.why_not}};
  return {{"ok", true},
          {"mu_s", f.mu_s},
          {"mu_s_error", f.mu_s_error},
          {"mu_2", f.mu_2},
          {"mu_2_error", f.mu_2_error},
          {"i_0", f.i_0},
          {"i_0_error", f.i_0_error},
          {"rms", f.rms},
          {"points", f.points}};
}

void print_fits(const MuIFit& mu, const LineFit& line, const LineFit& phi) {
  if (mu.ok)
    fmt::print("  mu(I) = mu_s + (mu_2 - mu_s) / (I_0 / I + 1): mu_s = {:.4f} +- {:.4f}, mu_2 = "
               "{:.4f} +- {:.4f}, I_0 = {:.4g} +- {:.2g}; rms {:.2g}\n",
               mu.mu_s, mu.mu_s_error, mu.mu_2, mu.mu_2_error, mu.i_0, mu.i_0_error, mu.rms);
  else
    fmt::print("  mu(I): no fit: {}\n", mu.why_not);
  if (line.ok)
    fmt::print("  mu = mu_1 + b I: mu_1 = {:.4f} +- {:.4f}, b = {:.3f} +- {:.3f}; rms {:.2g}\n",
               line.intercept, line.intercept_error, line.slope, line.slope_error, line.rms);
  if (phi.ok)
    fmt::print("  phi = phi_max - a I: phi_max = {:.4f} +- {:.4f}, a = {:.3f} +- {:.3f}; rms "
               "{:.2g}\n",
               phi.intercept, phi.intercept_error, -phi.slope, phi.slope_error, phi.rms);
  else
    fmt::print("  phi(I): no fit: {}\n", phi.why_not);
}

} // namespace

void analyze_sweep_rheology(const fs::path& dir, const AnalysisOptions& o) {
  const SweepPlan plan = read_plan(dir);
  std::string header = "run,";
  for (const SweepAxis& a : plan.axes) header += a.key + ",";
  std::string csv = header + "seed,measured,inertial,inertial_error,friction,friction_error,"
                             "packing,packing_error,shear_rate,pressure\n";
  std::vector<double> in, mu, phi;
  std::size_t analysed = 0;
  for (const SweepRun& r : plan.runs) {
    if (!fs::exists(dir / r.name / "run.json")) continue; // not run yet
    const RheologyPoint p = [&] {
      if (is_3d_run_folder(dir / r.name)) return run_rheology3(dir / r.name, o);
      RunData data{dir / r.name};
      return run_rheology(data, o);
    }();
    ++analysed;
    csv += r.name + ",";
    for (const auto& v : r.values) csv += csv_cell(v) + ",";
    csv +=
        fmt::format("{},{},{},{},{},{},{},{},{},{}\n", r.seed, p.measured ? 1 : 0,
                    csv_number(p.inertial), csv_number(p.inertial_error), csv_number(p.friction),
                    csv_number(p.friction_error), csv_number(p.packing),
                    csv_number(p.packing_error), csv_number(p.shear_rate), csv_number(p.pressure));
    if (!p.measured) {
      fmt::print("{}: not measured: {}\n", r.name, p.why_not);
      continue;
    }
    fmt::print("{}: I = {:.4f} +- {:.4f}, mu = {:.4f} +- {:.4f}, phi = {:.4f} +- {:.4f}\n", r.name,
               p.inertial, p.inertial_error, p.friction, p.friction_error, p.packing,
               p.packing_error);
    in.push_back(p.inertial), mu.push_back(p.friction), phi.push_back(p.packing);
  }
  if (analysed == 0)
    throw InvalidArgument("no run of the sweep in '" + dir.string() + "' has run yet");
  const MuIFit mu_fit = fit_mu_of_i(in, mu);
  const LineFit mu_line = fit_line(in, mu), phi_line = fit_line(in, phi);
  print_fits(mu_fit, mu_line, phi_line);
  const fs::path out = dir / "analysis";
  fs::create_directories(out);
  write_file_atomically((out / "rheology_points.csv").string(), csv);
  const json meta{{"points", in.size()},
                  {"mu_of_i", mu_json(mu_fit)},
                  {"mu_line", line_json(mu_line)},
                  {"phi_line", line_json(phi_line)}};
  write_file_atomically((out / "rheology.json").string(), meta.dump(2) + "\n");
  fmt::print("  points: {}\n  fits: {}\n", (out / "rheology_points.csv").string(),
             (out / "rheology.json").string());
  if (plot(out, "rheology_sweep", out / "rheology_points.csv", out / "rheology.png",
           out / "rheology.json"))
    fmt::print("  chart: {}\n", (out / "rheology.png").string());
}

} // namespace talus::cli
