// `talus analyze DIR jamming`: a run let down in steps of pressure (the built-in `jamming`): the
// packing fraction and the load-bearing coordination at rest after each step, and the jamming
// point fitted to them (post/jamming.hpp).
#include <cmath>
#include <map>
#include <sstream>

#include <fmt/core.h>

#include "cli/analyze/analyses.hpp"
#include "cli/analyze/csv_rows.hpp"
#include "io/checkpoint.hpp"
#include "post/jamming.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

using CsvRows = std::vector<CsvRow>;

CsvRows read_rows(const fs::path& file) {
  return read_csv_rows(file, "jamming");
}

double number(const CsvRow& row, const std::string& key) {
  return csv_value(row, key, "jamming", "thermo.csv",
                   "the run needs output.stress = true and a "
                   "stress_region");
}

// Each stage's means over its last quarter, and how near rest its last row came.
JammingStep step_of(const CsvRows& thermo, const std::string& name, double start, double end) {
  JammingStep s;
  s.name = name;
  const double from = end - 0.25 * (end - start);
  double n = 0.0, z2 = 0.0;
  const std::map<std::string, std::string>* last = nullptr;
  for (const auto& row : thermo) {
    const double t = number(row, "time");
    if (t < from || t > end) continue;
    s.pressure += number(row, "pressure"), s.packing += number(row, "region_packing_fraction");
    const double z = number(row, "load_bearing_coordination");
    s.coordination += z, z2 += z * z, s.rattlers += number(row, "rattler_fraction"), n += 1.0;
    last = &row;
  }
  if (n == 0.0) throw InvalidArgument("jamming: no thermo row in the last quarter of " + name);
  s.pressure /= n, s.packing /= n, s.coordination /= n, s.rattlers /= n;
  s.coordination_spread = std::sqrt(std::max(0.0, z2 / n - s.coordination * s.coordination));
  const double elastic = number(*last, "elastic");
  s.kinetic_over_elastic = elastic > 0.0 ? number(*last, "kinetic_translational") / elastic : 0.0;
  return s;
}

} // namespace

Section analyze_jamming(RunData& run, const AnalysisOptions&) {
  const CsvRows thermo = read_rows(run.dir() / "thermo.csv");
  std::vector<JammingStep> steps;
  for (const auto& st : read_rows(run.dir() / "stages.csv"))
    steps.push_back(step_of(thermo, st.at("name"), std::stod(st.at("start_time")),
                            std::stod(st.at("end_time"))));
  const JammingFit f = fit_jamming(steps);
  const fs::path out = run.out();
  std::string csv = "stage,pressure,packing_fraction,coordination,coordination_spread,"
                    "rattler_fraction,kinetic_over_elastic\n";
  for (const JammingStep& s : steps)
    csv += fmt::format("\"{}\",{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.6g}\n", s.name, s.pressure,
                       s.packing, s.coordination, s.coordination_spread, s.rattlers,
                       s.kinetic_over_elastic);
  write_file_atomically((out / "jamming.csv").string(), csv);
  write_file_atomically(
      (out / "jamming.json").string(),
      fmt::format("{{\"measured\": {}, \"why_not\": \"{}\", \"phi_j\": {}, \"phi_j_error\": {}, "
                  "\"bulk\": {}, \"bulk_error\": {}, \"z_j\": {}, \"z_j_error\": {}, "
                  "\"z_slope\": {}, \"z_slope_error\": {}}}\n",
                  f.measured, f.why_not, json_number(f.phi_j), json_number(f.phi_j_error),
                  json_number(f.bulk), json_number(f.bulk_error), json_number(f.z_j),
                  json_number(f.z_j_error), json_number(f.z_slope), json_number(f.z_slope_error)));
  Section s{"Jamming", {}, {}, {}};
  s.summary = fmt::format(
      "At the end of each of {} stages (means over its last quarter): the stress region's "
      "pressure, packing fraction and the coordination of its load-bearing network (rattlers "
      "out), and the fits phi = phi_J + p / B and Z = Z_J + A sqrt(phi - phi_J) (O'Hern et al. "
      "2003: phi_J about 0.84 and Z_J = 4 for 50:50 frictionless disks of size ratio 1.4).",
      steps.size());
  const std::string fitted = f.measured
                                 ? fmt::format("phi_J = {:.4f} +- {:.4f}, Z_J = {:.2f} +- {:.2f}",
                                               f.phi_j, f.phi_j_error, f.z_j, f.z_j_error)
                                 : "not fitted: " + f.why_not;
  s.numbers = {{"jamming point", fitted},
               {"B = dp/dphi", fmt::format("{:.4g} +- {:.2g} N/m", f.bulk, f.bulk_error)},
               {"A of Z - Z_J", fmt::format("{:.3g} +- {:.2g}", f.z_slope, f.z_slope_error)}};
  fmt::print("jamming: {} ({} stages)\n", fitted, steps.size());
  if (plot(out, "jamming", out / "jamming.csv", out / "jamming.png", out / "jamming.json"))
    s.charts.push_back(out / "jamming.png");
  for (const auto& chart : s.charts) fmt::print("  chart: {}\n", chart.string());
  return s;
}

} // namespace talus::cli
