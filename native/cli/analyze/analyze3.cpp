// `talus analyze DIR [WHAT]` for a run of spheres in 3D: the coarse-grained fields along an axis
// (post/coarse_grain.hpp) from the snapshots' spheres and contacts, the rheology of a sheared
// cell (post/rheology.hpp), and the report.
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/core.h>

#include "cli/analyze/analyses.hpp"
#include "cli/analyze/csv_rows.hpp"
#include "cli/pictures/pictures.hpp"
#include "io/checkpoint.hpp"
#include "io/vtp_reader.hpp"
#include "post/coarse_grain.hpp"
#include "post/rheology.hpp"
#include "scenario/file/load3.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

constexpr const char* axis_names[3] = {"x", "y", "z"};

// The snapshots from `from` on, each with its contacts (or without them).
std::vector<Frame3> frames3_from(const fs::path& dir, double from, bool contacts = true) {
  std::vector<Frame3> out;
  for (const Snapshot& s : snapshots_of(dir)) {
    if (s.time < from - 1e-12) continue;
    if (!contacts) {
      out.push_back(read_vtp_frame3(s.particles.string(), s.time));
      continue;
    }
    if (!fs::exists(s.contacts))
      throw InvalidArgument(fmt::format("{} is missing (a run by a talus that wrote no contacts "
                                        "in 3D): run the scenario again to coarse-grain it",
                                        s.contacts.string()));
    out.push_back(read_vtp_frame3(s.particles.string(), s.time, s.contacts.string()));
  }
  if (out.empty())
    throw InvalidArgument(fmt::format("--from {}: the run has no snapshots from then on", from));
  return out;
}

// The profile's axis: --axis, else the one gravity pulls along most (a bed's depth), else y (a
// sheared cell's gradient).
int profile_axis(const Scenario3& s, const std::string& axis) {
  if (!axis.empty()) return axis == "x" ? 0 : (axis == "y" ? 1 : 2);
  const Vec3& g = s.simulation.gravity;
  if (g.x == 0.0 && g.y == 0.0 && g.z == 0.0) return 1;
  const double a[3] = {std::abs(g.x), std::abs(g.y), std::abs(g.z)};
  return static_cast<int>(std::max_element(a, a + 3) - a);
}

// The free spheres' extent over the frames along each axis (their surfaces), and the box's
// where every frame is periodic along it (its mean over the frames: a cell's sides change).
struct Extents {
  Vec3 lo, hi;
  std::array<bool, 3> periodic{true, true, true};
};

Extents extents_of(const std::vector<Frame3>& frames) {
  const double big = std::numeric_limits<double>::max();
  Extents e{{big, big, big}, {-big, -big, -big}};
  Vec3 box_lo{}, box_hi{};
  for (const Frame3& f : frames) {
    for (std::size_t i = 0; i < f.position.size(); ++i)
      if (f.kind[i] == 0)
        for (int a = 0; a < 3; ++a) {
          component(e.lo, a) =
              std::min(component(e.lo, a), component(f.position[i], a) - f.radius[i]);
          component(e.hi, a) =
              std::max(component(e.hi, a), component(f.position[i], a) + f.radius[i]);
        }
    for (int a = 0; a < 3; ++a) {
      const auto k = static_cast<std::size_t>(a);
      e.periodic[k] = e.periodic[k] && f.periodic[k] && component(f.box_hi - f.box_lo, a) > 0.0;
    }
    box_lo += f.box_lo, box_hi += f.box_hi;
  }
  const double per = 1.0 / static_cast<double>(frames.size());
  if (!(e.hi.x > e.lo.x)) throw InvalidArgument("fields: the snapshots hold no free spheres");
  for (int a = 0; a < 3; ++a)
    if (e.periodic[static_cast<std::size_t>(a)])
      component(e.lo, a) = per * component(box_lo, a),
                      component(e.hi, a) = per * component(box_hi, a);
  return e;
}

double mean_free_radius(const Frame3& f) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < f.radius.size(); ++i)
    if (f.kind[i] == 0) sum += f.radius[i], ++n;
  if (n == 0) throw InvalidArgument("fields: the first snapshot has no free spheres");
  return sum / static_cast<double>(n);
}

// The kernel's width: --width, else the mean sphere radius (Lucy's kernel, which reaches its
// width and no farther: twice it), as 2D's kernel_width.
double kernel_width3(const std::vector<Frame3>& frames, CgKernel kernel, const AnalysisOptions& a) {
  if (a.width > 0.0) return a.width;
  return (kernel == CgKernel::lucy ? 2.0 : 1.0) * mean_free_radius(frames.front());
}

std::string fields3_csv(const FieldProfile3& p, const char* name) {
  std::string csv = fmt::format(
      "{},density,velocity_x,velocity_y,velocity_z,kinetic_xx,kinetic_yy,kinetic_zz,kinetic_xy,"
      "kinetic_xz,kinetic_yz,contact_xx,contact_xy,contact_xz,contact_yx,contact_yy,contact_yz,"
      "contact_zx,contact_zy,contact_zz\n",
      name);
  for (std::size_t k = 0; k < p.at.size(); ++k) {
    const Vec3 v = p.velocity(k);
    const Tensor3& K = p.kinetic[k];
    const Tensor3& C = p.contact[k];
    csv += fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}", p.at[k], p.density[k], v.x, v.y, v.z);
    for (const double x : {K(0, 0), K(1, 1), K(2, 2), K(0, 1), K(0, 2), K(1, 2)})
      csv += fmt::format(",{:.9g}", x);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) csv += fmt::format(",{:.9g}", C(a, b));
    csv += "\n";
  }
  return csv;
}

Section analyze_fields3(const fs::path& dir, const Scenario3& s, const AnalysisOptions& a) {
  if (a.map)
    throw InvalidArgument("fields --map: maps are of 2D runs; a 3D run has profiles along x, y "
                          "or z (--axis)");
  const std::vector<Frame3> frames = frames3_from(dir, std::max(a.from, 0.0));
  CgOptions3 o;
  o.kernel = parse_cg_kernel(a.kernel);
  o.axis = profile_axis(s, a.axis);
  o.width = kernel_width3(frames, o.kernel, a);
  const Extents e = extents_of(frames);
  const auto k = static_cast<std::size_t>(o.axis);
  o.lo = component(e.lo, o.axis), o.hi = component(e.hi, o.axis);
  if (e.periodic[k])
    o.period = o.hi - o.lo; // each frame's box scaled to the mean along the axis
  else
    o.lo -= 4.0 * o.width, o.hi += 4.0 * o.width; // past a Gaussian's tails
  for (int b = 0; b < 3; ++b)
    if (b != o.axis && !e.periodic[static_cast<std::size_t>(b)])
      o.extent[static_cast<std::size_t>(b)] = component(e.hi - e.lo, b);
  o.points = static_cast<std::size_t>(
      std::clamp(std::ceil(4.0 * (o.hi - o.lo) / o.width) + 1.0, 50.0, 4000.0));
  const FieldProfile3 p = coarse_grain(frames, o);

  double mass = 0.0;
  for (const Frame3& f : frames)
    for (std::size_t i = 0; i < f.mass.size(); ++i)
      if (f.kind[i] == 0) mass += f.mass[i];
  mass /= static_cast<double>(frames.size());
  double mass_integral = 0.0;
  Tensor3 contact_integral = Tensor3::Zero();
  const double dx = (o.hi - o.lo) / static_cast<double>(o.points - 1);
  for (std::size_t j = 0; j < p.at.size(); ++j) {
    const double w = (j == 0 || j + 1 == p.at.size() ? 0.5 : 1.0) * dx * p.across; // trapezoids
    mass_integral += w * p.density[j], contact_integral += w * p.contact[j];
  }
  const char* name = axis_names[k];
  const fs::path out = dir / "analysis";
  fs::create_directories(out);
  write_file_atomically((out / "fields.csv").string(), fields3_csv(p, name));
  std::string integral;
  for (int r = 0; r < 3; ++r)
    integral +=
        fmt::format("{}[{}, {}, {}]", r ? ", " : "", json_number(contact_integral(r, 0)),
                    json_number(contact_integral(r, 1)), json_number(contact_integral(r, 2)));
  write_file_atomically(
      (out / "fields.json").string(),
      fmt::format("{{\"dimension\": 3, \"axis\": \"{}\", \"kernel\": \"{}\", \"width\": {}, "
                  "\"across\": {}, \"points\": {}, \"frames\": {}, \"from\": {}, \"to\": {}, "
                  "\"mass\": {}, \"mass_integral\": {}, \"contact_integral\": [{}]}}\n",
                  name, cg_kernel_name(o.kernel), json_number(o.width), json_number(p.across),
                  o.points, frames.size(), json_number(frames.front().time),
                  json_number(frames.back().time), json_number(mass), json_number(mass_integral),
                  integral));
  Section sec{"Coarse-grained fields", {}, {}, {}};
  sec.summary = fmt::format(
      "Density, velocity and stress (kinetic and contact, compression positive, Pa) of the spheres "
      "along {}, coarse-grained with a {} kernel of width {:.3g} m over a cross-section of {:.3g} "
      "m^2 (Weinhart et al. 2012), averaged over {} snapshots from t = {:.3g} to {:.3g} s.",
      name, cg_kernel_name(o.kernel), o.width, p.across, frames.size(), frames.front().time,
      frames.back().time);
  sec.numbers = {{"kernel, width", fmt::format("{}, {:.3g} m", cg_kernel_name(o.kernel), o.width)},
                 {"mass: spheres, integral of the density",
                  fmt::format("{:.6g} kg, {:.6g} kg", mass, mass_integral)},
                 {"snapshots", fmt::format("{}", frames.size())}};
  fmt::print("fields: along {}, {} kernel of width {:.3g} m, {} snapshots; mass {:.6g} kg, "
             "integral of the density {:.6g} kg\n",
             name, cg_kernel_name(o.kernel), o.width, frames.size(), mass, mass_integral);
  if (plot(out, "fields3", out / "fields.csv", out / "fields.png", out / "fields.json"))
    sec.charts.push_back(out / "fields.png");
  for (const auto& chart : sec.charts) fmt::print("  chart: {}\n", chart.string());
  return sec;
}

bool sheared_cell3(const Scenario3& s) {
  return std::any_of(s.drivers.begin(), s.drivers.end(),
                     [](const Driver3Section& d) { return d.cell && d.shear_rate != 0.0; });
}

// The sheared cell's rows of thermo.csv from `from` on: its stress (thermo.csv's stress_* are the
// total in 3D, kinetic part included), packing fraction and shear rate.
std::vector<CellShearRow> cell_rows3(const fs::path& dir, double from) {
  const std::string needs = "a sheared cell's run needs output.stress = true";
  std::vector<CellShearRow> out;
  for (const CsvRow& row : read_csv_rows(dir / "thermo.csv", "rheology")) {
    const auto value = [&](const char* key) {
      return csv_value(row, key, "rheology", "thermo.csv", needs);
    };
    if (value("time") < from) continue;
    out.push_back({.time = value("time"),
                   .shear_stress = 0.5 * (value("stress_xy") + value("stress_yx")),
                   .normal_stress = value("stress_yy"),
                   .packing = value("region_packing_fraction"),
                   .shear_rate = value("cell_shear_rate")});
  }
  return out;
}

// Where the steady half starts: --from, else the middle of the snapshots' span.
double steady_from3(const fs::path& dir, const AnalysisOptions& a) {
  if (a.from >= 0.0) return a.from;
  const std::vector<Snapshot> all = snapshots_of(dir);
  return 0.5 * (all.front().time + all.back().time);
}

// A layer periodic along x and y on a rough floor, with gravity tilted down x: a chute.
bool chute3(const Scenario3& s) {
  const auto& p = s.geometry.periodic;
  return p[0] && p[1] && !p[2] && s.simulation.gravity.x != 0.0;
}

Section analyze_chute_run3(const fs::path& dir, const Scenario3& s, const AnalysisOptions& a) {
  if (!chute3(s))
    throw InvalidArgument("chute: needs a layer periodic along x and y (geometry.periodic = "
                          "\"xy\") on a rough floor (geometry.rough_floor = true), with gravity "
                          "tilted down x (a simulation.gravity with an x component)");
  const std::vector<Frame3> frames = frames3_from(dir, steady_from3(dir, a));
  ChuteOptions3 o;
  o.kernel = parse_cg_kernel(a.kernel);
  o.width = kernel_width3(frames, o.kernel, a);
  o.gravity = s.simulation.gravity;
  return analyze_chute3(dir / "analysis", frames, o);
}

Section analyze_rheology3(const fs::path& dir, const AnalysisOptions& a) {
  const RheologyPoint r = run_rheology3(dir, a);
  const double from = steady_from3(dir, a);
  const std::size_t blocks = RheologyOptions{}.blocks;
  const fs::path out = dir / "analysis";
  fs::create_directories(out);
  write_file_atomically((out / "rheology.json").string(), rheology_json(r) + "\n");
  Section sec{"Rheology of the simple shear", {}, {}, {}};
  sec.summary = fmt::format(
      "Simple shear of spheres in a sheared (Lees-Edwards) cell from t = {:.3g} s on: mu = "
      "|sigma_xy| / sigma_yy (Pa, kinetic part included) and the packing fraction of the cell "
      "(thermo.csv), with the inertial number I = gamma_dot d / sqrt(P / rho) (GDR MiDi 2004) from "
      "the cell's shear rate, rho a sphere's mass over its volume; errors from {} consecutive "
      "blocks. The slope of the spheres' own velocity profile in the snapshots checks that the "
      "shear is uniform.",
      from, blocks);
  sec.numbers = {{"flow", rheology_point_text(r, "Pa")}};
  fmt::print("rheology: {}\n", rheology_point_text(r, "Pa"));
  return sec;
}

std::vector<std::pair<std::string, std::string>> scenario3_rows(const Scenario3& s) {
  const Box3Section& g = s.geometry;
  std::string periodic;
  for (std::size_t a = 0; a < 3; ++a)
    if (g.periodic[a]) periodic += axis_names[a];
  const Vec3& gravity = s.simulation.gravity;
  return {{"dimension", "3 (spheres)"},
          {"spheres", fmt::format("{}", s.particles.count)},
          {"box", fmt::format("[{:g}, {:g}, {:g}] to [{:g}, {:g}, {:g}] m", g.lo.x, g.lo.y, g.lo.z,
                              g.hi.x, g.hi.y, g.hi.z)},
          {"periodic", periodic.empty() ? "none" : periodic},
          {"gravity", fmt::format("[{:g}, {:g}, {:g}] m/s^2", gravity.x, gravity.y, gravity.z)},
          {"duration", fmt::format("{:g} s", s.simulation.duration)},
          {"drivers", fmt::format("{}", s.drivers.size())}};
}

} // namespace

RheologyPoint run_rheology3(const fs::path& dir, const AnalysisOptions& a) {
  const fs::path toml = dir / "scenario.toml";
  if (!sheared_cell3(load_scenario3(read_file(toml.string()), toml.string())))
    throw InvalidArgument("rheology: a 3D run's rheology is that of a sheared cell (a cell driver "
                          "with a shear_rate), as the built-in simple_shear3d");
  const double from = steady_from3(dir, a); // the steady half
  return cell_rheology_point(cell_rows3(dir, from), frames3_from(dir, from, false),
                             RheologyOptions{}.blocks);
}

void analyze_3d_run(const fs::path& dir, const std::string& what, const AnalysisOptions& o) {
  const std::vector<std::string> analyses3{"thermo", "forces", "fields", "rheology", "chute"};
  if (what != "all" && std::find(analyses3.begin(), analyses3.end(), what) == analyses3.end()) {
    check_analysis_name(what);
    throw InvalidArgument("analyze: '" + dir.string() +
                          "' is a run of spheres in 3D, whose "
                          "analyses are thermo, forces, fields, rheology and chute (and all, with "
                          "report.html); " +
                          what + " takes 2D runs for now");
  }
  const fs::path toml = dir / "scenario.toml";
  const Scenario3 s = load_scenario3(read_file(toml.string()), toml.string());
  std::vector<Section> sections;
  const fs::path out = dir / "analysis";
  if (what == "thermo") {
    analyze_thermo(dir, out);
  } else if (!fs::exists(dir / "particles.pvd")) {
    if (what != "all")
      throw InvalidArgument(what + ": '" + dir.string() +
                            "' has no snapshots (output.snapshot_interval = 0)");
    fmt::print("no snapshots (output.snapshot_interval = 0): only thermo applies\n");
    sections.push_back(analyze_thermo(dir, out));
  } else if (what == "forces") {
    analyze_forces(dir, out, o);
  } else if (what == "fields") {
    analyze_fields3(dir, s, o);
  } else if (what == "rheology") {
    analyze_rheology3(dir, o);
  } else if (what == "chute") {
    analyze_chute_run3(dir, s, o);
  } else {
    // every one that applies; one that cannot run says why and the others go on
    const auto attempt = [&](const char* name, auto&& analysis) {
      try {
        sections.push_back(analysis());
      } catch (const InvalidArgument& e) {
        fmt::print("{}: skipped ({})\n", name, e.what());
      }
    };
    attempt("thermo", [&] { return analyze_thermo(dir, out); });
    attempt("forces", [&] { return analyze_forces(dir, out, o); });
    attempt("fields", [&] { return analyze_fields3(dir, s, o); });
    if (sheared_cell3(s) && s.output.stress)
      attempt("rheology", [&] { return analyze_rheology3(dir, o); });
    if (chute3(s)) attempt("chute", [&] { return analyze_chute_run3(dir, s, o); });
  }
  if (what == "all")
    fmt::print("report: {}\n", write_report_page(dir, dir / "analysis", s.name, s.description,
                                                 scenario3_rows(s), sections)
                                   .string());
}

} // namespace talus::cli
