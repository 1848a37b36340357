// `talus analyze DIR rheology`: the friction coefficient, packing fraction and inertial number of
// a steady plane shear flow between rough walls (post/rheology.hpp), with the profiles across the
// layer they come from, or of simple shear in a sheared (Lees-Edwards) cell, from the cell's own
// stress.
#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "cli/analyze/analyses.hpp"
#include "cli/analyze/csv_rows.hpp"
#include "io/checkpoint.hpp"
#include "post/rheology.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

// The sheared cell's rows of thermo.csv from `from` on.
std::vector<CellShearRow> cell_rows(RunData& run, double from) {
  const std::string needs = "a sheared cell's run needs output.stress = true";
  std::vector<CellShearRow> out;
  for (const CsvRow& row : read_csv_rows(run.dir() / "thermo.csv", "rheology")) {
    const auto value = [&](const char* key) {
      return csv_value(row, key, "rheology", "thermo.csv", needs);
    };
    if (value("time") < from) continue;
    // thermo.csv's stress_* are the contact part; the kinetic part counts too
    out.push_back({.time = value("time"),
                   .shear_stress =
                       0.5 * (value("stress_xy") + value("stress_yx")) + value("kinetic_stress_xy"),
                   .normal_stress = value("stress_yy") + value("kinetic_stress_yy"),
                   .packing = value("packing_fraction"),
                   .shear_rate = value("cell_shear_rate")});
  }
  return out;
}

RheologyPoint cell_point(RunData& run, const AnalysisOptions& a) {
  const double from = steady_from(run, a);
  return cell_rheology_point(cell_rows(run, from), run.frames(from), RheologyOptions{}.blocks);
}

RheologyOptions options_of(RunData& run, const AnalysisOptions& a) {
  const Scenario& s = run.scenario();
  if (s.geometry.periodic != "x")
    throw InvalidArgument("rheology: needs a layer periodic along x (geometry.periodic = \"x\") "
                          "sheared between wall grains below and above it, as the built-in "
                          "shear, or a sheared cell (a cell driver with a shear_rate), as the "
                          "built-in simple_shear; this run's geometry.periodic is \"" +
                          s.geometry.periodic + "\"");
  RheologyOptions o;
  o.kernel = parse_cg_kernel(a.kernel);
  o.width = kernel_width(run, a);
  o.across = s.geometry.box->hi.x - s.geometry.box->lo.x;
  return o;
}

// The profiles across the whole gap, for the chart: velocity, packing fraction, mu, pressure.
std::string profile_csv(const std::vector<Frame>& frames, const RheologyOptions& o,
                        const RheologyPoint& r) {
  CgOptions cg;
  cg.kernel = o.kernel, cg.width = o.width, cg.axis = 1, cg.across = o.across;
  cg.lo = r.base, cg.hi = r.plate, cg.points = 81;
  const FieldProfile p = coarse_grain(frames, cg);
  std::string csv = "y,velocity_x,packing_fraction,friction,pressure,bulk\n";
  for (std::size_t k = 0; k < p.at.size(); ++k) {
    const Tensor2 s = p.contact[k] + p.kinetic[k];
    const double shear = std::abs(0.5 * (s(0, 1) + s(1, 0)));
    const bool bulk = p.at[k] >= r.bulk_lo && p.at[k] <= r.bulk_hi;
    csv += fmt::format("{:.6g},{:.9g},{:.9g},{},{:.9g},{}\n", p.at[k], p.velocity(k).x,
                       p.density[k] / r.grain_density,
                       csv_number(s(1, 1) > 0.0 ? shear / s(1, 1) : std::nan("")), s(1, 1),
                       bulk ? 1 : 0);
  }
  return csv;
}

} // namespace

std::string rheology_point_text(const RheologyPoint& r, const char* stress_unit) {
  if (!r.measured) return "not measured: " + r.why_not;
  const std::string profile = r.profile_shear_rate != 0.0
                                  ? fmt::format(", the grains' profile {:.4g} +- {:.2g} 1/s",
                                                r.profile_shear_rate, r.profile_shear_rate_error)
                                  : "";
  return fmt::format("I = {:.4f} +- {:.4f}, mu = {:.4f} +- {:.4f}, phi = {:.4f} +- {:.4f} "
                     "(shear rate {:.4g} 1/s{}, pressure {:.4g} {})",
                     r.inertial, r.inertial_error, r.friction, r.friction_error, r.packing,
                     r.packing_error, r.shear_rate, profile, r.pressure, stress_unit);
}

bool sheared_cell(const Scenario& s) {
  for (const DriverSection& d : s.drivers)
    if (d.type == "cell" && d.shear_rate != 0.0) return true;
  return false;
}

RheologyPoint run_rheology(RunData& run, const AnalysisOptions& a) {
  if (sheared_cell(run.scenario())) return cell_point(run, a);
  const RheologyOptions o = options_of(run, a);
  return rheology_point(run.frames_with_contacts(steady_from(run, a)), o);
}

std::string rheology_json(const RheologyPoint& r) {
  return fmt::format(
      "{{\"measured\": {}, \"why_not\": \"{}\", \"frames\": {}, \"base\": {}, \"plate\": {}, "
      "\"bulk_lo\": {}, \"bulk_hi\": {}, \"diameter\": {}, \"grain_density\": {}, "
      "\"shear_rate\": {}, \"shear_rate_error\": {}, \"pressure\": {}, \"pressure_error\": {}, "
      "\"shear_stress\": {}, \"shear_stress_error\": {}, \"friction\": {}, \"friction_error\": {}, "
      "\"packing\": {}, \"packing_error\": {}, \"inertial\": {}, \"inertial_error\": {}, "
      "\"profile_shear_rate\": {}, \"profile_shear_rate_error\": {}}}",
      r.measured, r.why_not, r.frames, json_number(r.base), json_number(r.plate),
      json_number(r.bulk_lo), json_number(r.bulk_hi), json_number(r.diameter),
      json_number(r.grain_density), json_number(r.shear_rate), json_number(r.shear_rate_error),
      json_number(r.pressure), json_number(r.pressure_error), json_number(r.shear_stress),
      json_number(r.shear_stress_error), json_number(r.friction), json_number(r.friction_error),
      json_number(r.packing), json_number(r.packing_error), json_number(r.inertial),
      json_number(r.inertial_error), json_number(r.profile_shear_rate),
      json_number(r.profile_shear_rate_error));
}

// A sheared cell: its numbers, no profile (every grain is in the bulk).
Section analyze_cell_rheology(RunData& run, const AnalysisOptions& a) {
  const RheologyPoint r = cell_point(run, a);
  write_file_atomically((run.out() / "rheology.json").string(), rheology_json(r) + "\n");
  Section s{"Rheology of the simple shear", {}, {}, {}};
  s.summary = fmt::format(
      "Simple shear in a sheared (Lees-Edwards) cell from t = {:.3g} s on: mu = |sigma_xy| / "
      "sigma_yy and the packing fraction of the whole cell (thermo.csv, kinetic part included), "
      "with the inertial number I = gamma_dot d / sqrt(P / rho) (GDR MiDi 2004) from the cell's "
      "shear rate; errors from {} consecutive blocks. The slope of the grains' own velocity "
      "profile in the snapshots checks that the shear is uniform.",
      steady_from(run, a), RheologyOptions{}.blocks);
  s.numbers = {{"flow", rheology_point_text(r)}};
  fmt::print("rheology: {}\n", rheology_point_text(r));
  return s;
}

Section analyze_rheology(RunData& run, const AnalysisOptions& a) {
  if (sheared_cell(run.scenario())) return analyze_cell_rheology(run, a);
  const RheologyOptions o = options_of(run, a);
  const std::vector<Frame> frames = run.frames_with_contacts(steady_from(run, a));
  const RheologyPoint r = rheology_point(frames, o);
  const fs::path out = run.out();
  if (r.measured) write_file_atomically((out / "rheology.csv").string(), profile_csv(frames, o, r));
  write_file_atomically((out / "rheology.json").string(), rheology_json(r) + "\n");
  Section s{"Rheology of the shear flow", {}, {}, {}};
  s.summary = fmt::format(
      "The steady flow of {} snapshots from t = {:.3g} s, coarse-grained across the layer ({} "
      "kernel of width {:.3g} m) and measured in the middle half of the gap between the rough "
      "walls: the shear rate (the slope of v_x), mu = |sigma_xy| / sigma_yy and the packing "
      "fraction, with the inertial number I = gamma_dot d / sqrt(P / rho) (GDR MiDi 2004); errors "
      "from {} consecutive blocks of snapshots.",
      frames.size(), frames.front().time, cg_kernel_name(o.kernel), o.width, o.blocks);
  s.numbers = {{"flow", rheology_point_text(r)}};
  if (r.measured)
    s.numbers.push_back(
        {"bulk", fmt::format("y from {:.4g} to {:.4g} m of a gap {:.3g} d wide", r.bulk_lo,
                             r.bulk_hi, (r.plate - r.base) / r.diameter)});
  fmt::print("rheology: {}\n", rheology_point_text(r));
  if (r.measured &&
      plot(out, "rheology", out / "rheology.csv", out / "rheology.png", out / "rheology.json"))
    s.charts.push_back(out / "rheology.png");
  for (const auto& chart : s.charts) fmt::print("  chart: {}\n", chart.string());
  return s;
}

} // namespace talus::cli
