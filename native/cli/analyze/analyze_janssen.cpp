// `talus analyze DIR janssen`: the wall stress against depth in a silo at rest, and Janssen's
// saturation fitted to it (post/janssen.hpp).
#include <cmath>

#include <fmt/core.h>

#include "cli/analyze/analyses.hpp"
#include "io/checkpoint.hpp"
#include "post/janssen.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

Section analyze_janssen(RunData& run, const AnalysisOptions& a) {
  const Scenario& sc = run.scenario();
  const std::string& builder = sc.geometry.builder;
  if (builder != "silo" && builder != "box")
    throw InvalidArgument("janssen: needs a silo or a box (side walls at x = 0 and x = "
                          "geometry.width); this run's geometry.builder is \"" +
                          builder + "\"");
  JanssenOptions o;
  o.left = 0.0;
  o.right = sc.geometry.width;
  o.gravity = norm(sc.simulation.gravity);
  // a bed at rest: its last snapshot, unless --from asks for a mean over more
  const double from = a.from >= 0.0 ? a.from : run.frames(0.0).back().time;
  const std::vector<Frame> frames = run.frames_with_contacts(from);
  const JanssenProfile p = janssen_profile(frames, o);

  const fs::path out = run.out();
  std::string csv = "depth,wall_normal_stress,wall_shear_stress,fitted,fit\n";
  for (std::size_t k = 0; k < p.depth.size(); ++k)
    csv += fmt::format(
        "{:.6g},{:.9g},{:.9g},{},{}\n", p.depth[k], p.normal[k], p.shear[k], p.fitted[k] ? 1 : 0,
        csv_number(p.measured ? janssen_stress(p.saturation, p.length, p.depth[k]) : std::nan("")));
  write_file_atomically((out / "janssen.csv").string(), csv);
  write_file_atomically(
      (out / "janssen.json").string(),
      fmt::format("{{\"measured\": {}, \"why_not\": \"{}\", \"frames\": {}, \"from\": {}, "
                  "\"width\": {}, \"surface\": {}, \"base\": {}, \"bin\": {}, "
                  "\"weight_density\": {}, \"mobilised_friction\": {}, \"saturation\": {}, "
                  "\"saturation_error\": {}, \"length\": {}, \"length_error\": {}, \"rms\": {}, "
                  "\"predicted_saturation\": {}, \"stress_ratio\": {}}}\n",
                  p.measured, p.why_not, frames.size(), json_number(frames.front().time),
                  json_number(o.right - o.left), json_number(p.surface), json_number(p.base),
                  json_number(p.bin), json_number(p.weight_density),
                  json_number(p.mobilised_friction), json_number(p.saturation),
                  json_number(p.saturation_error), json_number(p.length),
                  json_number(p.length_error), json_number(p.rms),
                  json_number(p.predicted_saturation), json_number(p.stress_ratio)));
  Section s{"Janssen's wall stress", {}, {}, {}};
  s.summary = fmt::format(
      "The side walls' normal stress against depth below the free surface, from the wall "
      "contacts of {} snapshots (t >= {:.3g} s) in bins of {:.3g} m, and the fit of Janssen's "
      "sigma(z) = sigma_inf (1 - exp(-z / lambda)); Janssen's theory has sigma_inf = rho_b g W / "
      "(2 mu), mu the friction the walls mobilise, and lambda = W / (2 K mu).",
      frames.size(), frames.front().time, p.bin);
  const std::string fitted =
      p.measured ? fmt::format("sigma_inf = {:.4g} +- {:.2g} N/m, lambda = {:.4g} +- {:.2g} m",
                               p.saturation, p.saturation_error, p.length, p.length_error)
                 : "not fitted: " + p.why_not;
  s.numbers = {
      {"fit", fitted},
      {"Janssen's sigma_inf from the mobilised friction",
       fmt::format("{:.4g} N/m (mu = {:.3f}, rho_b g = {:.4g} N/m^2)", p.predicted_saturation,
                   p.mobilised_friction, p.weight_density)},
      {"K = W / (2 mu lambda)", fmt::format("{:.3f}", p.stress_ratio)},
      {"bed", fmt::format("{:.3g} m deep, {:.3g} m wide", p.surface - p.base, o.right - o.left)}};
  fmt::print("janssen: {}; Janssen's sigma_inf from mu = {:.3f}: {:.4g} N/m; K = {:.3f}\n", fitted,
             p.mobilised_friction, p.predicted_saturation, p.stress_ratio);
  if (plot(out, "janssen", out / "janssen.csv", out / "janssen.png", out / "janssen.json"))
    s.charts.push_back(out / "janssen.png");
  for (const auto& chart : s.charts) fmt::print("  chart: {}\n", chart.string());
  return s;
}

} // namespace talus::cli
