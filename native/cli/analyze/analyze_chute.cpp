// `talus analyze DIR chute`: a steady flow down a rough incline, its profiles across the layer
// and Bagnold's velocity profile fitted to them (post/chute.hpp).
#include <cmath>

#include <fmt/core.h>

#include "cli/analyze/analyses.hpp"
#include "io/checkpoint.hpp"
#include "post/block_mean.hpp"
#include "post/chute.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

// The standard errors of the bulk's mu, I and phi: their spread over consecutive blocks of the
// snapshots, each block's flow measured alone (blocks of a steady flow a few seconds long are
// nearly independent samples of it). NaN with too few snapshots or a block not measured.
struct BulkErrors {
  double friction = NAN, inertial = NAN, packing = NAN;
};

template <class FrameT, class Options>
BulkErrors bulk_errors(const std::vector<FrameT>& frames, const Options& o) {
  constexpr std::size_t blocks = 4;
  BulkErrors e;
  if (frames.size() < 2 * blocks) return e;
  std::vector<ChuteFlow> flows;
  const std::size_t per = frames.size() / blocks;
  for (std::size_t b = 0; b < blocks; ++b) {
    const auto first = frames.begin() + static_cast<std::ptrdiff_t>(b * per);
    const auto last = b + 1 == blocks ? frames.end() : first + static_cast<std::ptrdiff_t>(per);
    flows.push_back(chute_flow(std::vector<FrameT>(first, last), o));
    if (!flows.back().measured) return e;
  }
  e.friction = block_mean_error(flows, &ChuteFlow::bulk_friction).second;
  e.inertial = block_mean_error(flows, &ChuteFlow::bulk_inertial).second;
  e.packing = block_mean_error(flows, &ChuteFlow::bulk_packing).second;
  return e;
}

std::string profile_csv(const ChuteFlow& c) {
  std::string csv = "z,velocity,packing_fraction,friction,inertial,bagnold,fitted\n";
  for (std::size_t k = 0; k < c.z.size(); ++k) {
    const bool in = c.z[k] >= 0.0 && c.z[k] <= c.depth;
    const double bagnold =
        in ? c.bagnold.intercept +
                 c.bagnold.slope * (std::pow(c.depth, 1.5) - std::pow(c.depth - c.z[k], 1.5))
           : std::nan("");
    csv += fmt::format("{:.6g},{:.9g},{:.9g},{},{},{},{}\n", c.z[k], c.velocity[k], c.packing[k],
                       csv_number(c.friction[k]), csv_number(c.inertial[k]), csv_number(bagnold),
                       c.z[k] >= c.band_lo && c.z[k] <= c.band_hi ? 1 : 0);
  }
  return csv;
}

std::string chute_json(const ChuteFlow& c, const BulkErrors& e, const char* friction_of) {
  return fmt::format(
      "{{\"measured\": {}, \"why_not\": \"{}\", \"friction_of\": \"{}\", \"frames\": {}, "
      "\"angle_deg\": {}, "
      "\"tan_angle\": {}, \"base\": {}, \"depth\": {}, \"diameter\": {}, \"band_lo\": {}, "
      "\"band_hi\": {}, \"bulk_friction\": {}, \"bulk_friction_error\": {}, "
      "\"bulk_inertial\": {}, \"bulk_inertial_error\": {}, \"bulk_packing\": {}, "
      "\"bulk_packing_error\": {}, "
      "\"base_velocity\": {}, \"base_velocity_error\": {}, \"bagnold_c\": {}, "
      "\"bagnold_c_error\": {}, \"bagnold_rms\": {}, \"bagnold_inertial\": {}, "
      "\"straight_rms\": {}}}\n",
      c.measured, c.why_not, friction_of, c.frames, json_number(c.angle * 180.0 / M_PI),
      json_number(std::tan(c.angle)), json_number(c.base), json_number(c.depth),
      json_number(c.diameter), json_number(c.band_lo), json_number(c.band_hi),
      json_number(c.bulk_friction), json_number(e.friction), json_number(c.bulk_inertial),
      json_number(e.inertial), json_number(c.bulk_packing), json_number(e.packing),
      json_number(c.bagnold.intercept), json_number(c.bagnold.intercept_error),
      json_number(c.bagnold.slope), json_number(c.bagnold.slope_error), json_number(c.bagnold.rms),
      json_number(c.bagnold_inertial), json_number(c.straight.rms));
}

std::string flow_text(const ChuteFlow& c, const BulkErrors& e) {
  if (!c.measured) return "not measured: " + c.why_not;
  return fmt::format("{:.3g} d deep at {:.2f} deg: in the bulk mu = {:.4f} +- {:.2g} (tan theta = "
                     "{:.4f}), I = {:.4f} +- {:.2g}, phi = {:.4f} +- {:.2g}; Bagnold's profile v_b "
                     "+ c (h^1.5 - (h - z)^1.5): "
                     "v_b = {:.3f} m/s, c = {:.4g} +- {:.2g}, rms {:.3g} m/s (a straight profile: "
                     "{:.3g}), I from c = {:.4f}",
                     c.depth / c.diameter, c.angle * 180.0 / M_PI, c.bulk_friction, e.friction,
                     std::tan(c.angle), c.bulk_inertial, e.inertial, c.bulk_packing, e.packing,
                     c.bagnold.intercept, c.bagnold.slope, c.bagnold.slope_error, c.bagnold.rms,
                     c.straight.rms, c.bagnold_inertial);
}

// chute.csv, chute.json and the chart in `out`, and the report's section: `stress` names the
// friction's components (sigma_xy / sigma_yy in 2D, sigma_xz / sigma_zz in 3D).
Section chute_section(const fs::path& out, const ChuteFlow& c, const BulkErrors& errors,
                      double from, CgKernel kernel, double width, double margin,
                      const char* stress) {
  fs::create_directories(out);
  if (c.measured) write_file_atomically((out / "chute.csv").string(), profile_csv(c));
  write_file_atomically((out / "chute.json").string(), chute_json(c, errors, stress));
  Section sec{"Flow down the incline", {}, {}, {}};
  sec.summary = fmt::format(
      "The steady flow of {} snapshots from t = {:.3g} s, coarse-grained across the layer ({} "
      "kernel of width {:.3g} m): velocity, packing fraction, {} and the inertial number against "
      "the height above the base, and Bagnold's profile fitted from {} diameters above the base "
      "to as far below the surface (GDR MiDi 2004). The bulk's errors: the spread over four "
      "consecutive blocks of the snapshots.",
      c.frames, from, cg_kernel_name(kernel), width, stress, margin);
  sec.numbers = {{"flow", flow_text(c, errors)}};
  fmt::print("chute: {}\n", flow_text(c, errors));
  if (c.measured && plot(out, "chute", out / "chute.csv", out / "chute.png", out / "chute.json"))
    sec.charts.push_back(out / "chute.png");
  for (const auto& chart : sec.charts) fmt::print("  chart: {}\n", chart.string());
  return sec;
}

} // namespace

Section analyze_chute3(const fs::path& out, const std::vector<Frame3>& frames,
                       const ChuteOptions3& o) {
  const ChuteFlow c = chute_flow(frames, o);
  return chute_section(out, c, c.measured ? bulk_errors(frames, o) : BulkErrors{},
                       frames.front().time, o.kernel, o.width, o.margin, "|sigma_xz| / sigma_zz");
}

Section analyze_chute(RunData& run, const AnalysisOptions& a) {
  const Scenario& s = run.scenario();
  if (s.geometry.periodic != "x" || s.simulation.gravity.x == 0.0)
    throw InvalidArgument("chute: needs a layer periodic along x (geometry.periodic = \"x\") on "
                          "a base of wall grains, with gravity tilted down the slope (a "
                          "simulation.gravity with an x component), as the built-in chute");
  ChuteOptions o;
  o.kernel = parse_cg_kernel(a.kernel);
  o.width = kernel_width(run, a);
  o.across = s.geometry.box->hi.x - s.geometry.box->lo.x;
  o.gravity = s.simulation.gravity;
  const std::vector<Frame> frames = run.frames_with_contacts(steady_from(run, a));
  const ChuteFlow c = chute_flow(frames, o);
  return chute_section(run.out(), c, c.measured ? bulk_errors(frames, o) : BulkErrors{},
                       frames.front().time, o.kernel, o.width, o.margin, "|sigma_xy| / sigma_yy");
}

} // namespace talus::cli
