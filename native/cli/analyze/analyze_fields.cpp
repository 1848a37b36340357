// `talus analyze DIR fields`: coarse-grained profiles of density, velocity and stress along an
// axis (post/coarse_grain.hpp), averaged over the snapshots, with the totals they integrate to.
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/core.h>

#include "cli/analyze/analyses.hpp"
#include "io/checkpoint.hpp"
#include "post/coarse_grain.hpp"
#include "post/coarse_grain_map.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

double along(Vec2 v, int axis) {
  return axis == 0 ? v.x : v.y;
}

// The profile's span and the extent across from the scenario's periodic box where there is one
// along a direction, else from the free grains' extent over the frames.
void span_and_across(const Scenario& s, const std::vector<Frame>& frames, CgOptions& o) {
  double lo[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  double hi[2] = {-lo[0], -lo[1]};
  for (const Frame& f : frames)
    for (std::size_t i = 0; i < f.position.size(); ++i)
      if (f.kind[i] == 0)
        for (int a = 0; a < 2; ++a) {
          lo[a] = std::min(lo[a], along(f.position[i], a) - f.radius[i]);
          hi[a] = std::max(hi[a], along(f.position[i], a) + f.radius[i]);
        }
  if (!(hi[0] > lo[0])) throw InvalidArgument("fields: the snapshots hold no free grains");
  const std::string& periodic = s.geometry.periodic;
  const bool wraps[2] = {periodic == "x" || periodic == "xy", periodic == "y" || periodic == "xy"};
  const auto box = [&](int a, bool high) {
    const Rect& b = *s.geometry.box;
    return along(high ? b.hi : b.lo, a);
  };
  const int a = o.axis, b = 1 - o.axis;
  if (wraps[a]) {
    o.lo = box(a, false), o.hi = box(a, true), o.period = o.hi - o.lo;
  } else {
    o.lo = lo[a] - 4.0 * o.width, o.hi = hi[a] + 4.0 * o.width; // past a Gaussian's tails
  }
  o.across = wraps[b] ? box(b, true) - box(b, false) : hi[b] - lo[b];
}

// `--map`: the fields over the plane, in cells of --cell (default: the kernel's width).
Section analyze_field_map(RunData& run, const AnalysisOptions& a, const std::vector<Frame>& frames,
                          CgKernel kernel, double width) {
  CgMapOptions m;
  m.kernel = kernel, m.width = width;
  CgOptions along[2];
  for (int axis = 0; axis < 2; ++axis) {
    along[axis].axis = axis, along[axis].width = width;
    span_and_across(run.scenario(), frames, along[axis]);
  }
  m.lo = {along[0].lo, along[1].lo}, m.hi = {along[0].hi, along[1].hi};
  m.period = {along[0].period, along[1].period};
  const double cell = a.cell > 0.0 ? a.cell : width;
  m.nx = static_cast<std::size_t>(std::max(1.0, std::round((m.hi.x - m.lo.x) / cell)));
  m.ny = static_cast<std::size_t>(std::max(1.0, std::round((m.hi.y - m.lo.y) / cell)));
  if (m.nx * m.ny > 4'000'000)
    throw InvalidArgument(fmt::format("fields --map: {} x {} cells of {:.3g} m; allowed: up to 4e6 "
                                      "cells (a larger --cell)",
                                      m.nx, m.ny, cell));
  const FieldMap f = coarse_grain_map(frames, m);
  std::string csv = "x,y,density,velocity_x,velocity_y,kinetic_xx,kinetic_xy,kinetic_yy,"
                    "contact_xx,contact_xy,contact_yx,contact_yy\n";
  double mass_integral = 0.0;
  for (std::size_t k = 0; k < f.density.size(); ++k) {
    const Vec2 c = f.centre(k), v = f.velocity(k);
    const Tensor2& K = f.kinetic[k];
    const Tensor2& C = f.contact[k];
    csv +=
        fmt::format("{:.6g},{:.6g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},"
                    "{:.9g}\n",
                    c.x, c.y, f.density[k], v.x, v.y, K(0, 0), K(0, 1), K(1, 1), C(0, 0), C(0, 1),
                    C(1, 0), C(1, 1));
    mass_integral += f.density[k] * f.cell_x * f.cell_y;
  }
  const fs::path out = run.out();
  write_file_atomically((out / "fields_map.csv").string(), csv);
  write_file_atomically(
      (out / "fields_map.json").string(),
      fmt::format("{{\"kernel\": \"{}\", \"width\": {}, \"nx\": {}, \"ny\": {}, \"cell_x\": {}, "
                  "\"cell_y\": {}, \"frames\": {}, \"mass_integral\": {}}}\n",
                  cg_kernel_name(kernel), json_number(width), f.nx, f.ny, json_number(f.cell_x),
                  json_number(f.cell_y), f.frames, json_number(mass_integral)));
  Section s{"Coarse-grained field maps", {}, {}, {}};
  s.summary = fmt::format(
      "Density, velocity and stress (kinetic and contact, compression positive, N/m in 2D) over "
      "the plane in {} x {} cells, coarse-grained with a {} kernel of width {:.3g} m (Weinhart et "
      "al. 2012), averaged over {} snapshots.",
      f.nx, f.ny, cg_kernel_name(kernel), width, f.frames);
  s.numbers = {{"cells", fmt::format("{} x {} of {:.3g} m", f.nx, f.ny, f.cell_x)},
               {"mass, integral of the density", fmt::format("{:.6g} kg", mass_integral)}};
  fmt::print("fields: maps of {} x {} cells, {} kernel of width {:.3g} m, {} snapshots; integral "
             "of the density {:.6g} kg\n",
             f.nx, f.ny, cg_kernel_name(kernel), width, f.frames, mass_integral);
  if (plot(out, "fields_map", out / "fields_map.csv", out / "fields_map.png",
           out / "fields_map.json"))
    s.charts.push_back(out / "fields_map.png");
  for (const auto& chart : s.charts) fmt::print("  chart: {}\n", chart.string());
  return s;
}

} // namespace

Section analyze_fields(RunData& run, const AnalysisOptions& a) {
  const std::vector<Frame> frames = run.frames_with_contacts(std::max(a.from, 0.0));
  CgOptions o;
  o.kernel = parse_cg_kernel(a.kernel);
  if (a.axis == "z") throw InvalidArgument("fields --axis z: a 2D run's axes are x and y");
  o.axis = a.axis == "x" ? 0 : 1;
  o.width = kernel_width(run, a);
  if (a.map) return analyze_field_map(run, a, frames, o.kernel, o.width);
  span_and_across(run.scenario(), frames, o);
  o.points = static_cast<std::size_t>(
      std::clamp(std::ceil(4.0 * (o.hi - o.lo) / o.width) + 1.0, 50.0, 4000.0));
  const FieldProfile p = coarse_grain(frames, o);

  const char* name = o.axis == 0 ? "x" : "y";
  std::string csv = fmt::format("{},density,velocity_x,velocity_y,kinetic_xx,kinetic_xy,"
                                "kinetic_yy,contact_xx,contact_xy,contact_yx,contact_yy\n",
                                name);
  double mass_integral = 0.0;
  Tensor2 contact_integral = Tensor2::Zero();
  const double dy = (o.hi - o.lo) / static_cast<double>(o.points - 1);
  for (std::size_t k = 0; k < p.at.size(); ++k) {
    const Vec2 v = p.velocity(k);
    const Tensor2& K = p.kinetic[k];
    const Tensor2& C = p.contact[k];
    csv += fmt::format(
        "{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", p.at[k],
        p.density[k], v.x, v.y, K(0, 0), K(0, 1), K(1, 1), C(0, 0), C(0, 1), C(1, 0), C(1, 1));
    const double w = (k == 0 || k + 1 == p.at.size()) ? 0.5 * dy : dy; // trapezoids
    mass_integral += w * o.across * p.density[k];
    contact_integral += (w * o.across) * C;
  }
  double mass = 0.0;
  for (const Frame& f : frames)
    for (std::size_t i = 0; i < f.mass.size(); ++i)
      if (f.kind[i] == 0) mass += f.mass[i];
  mass /= static_cast<double>(frames.size());

  const fs::path out = run.out();
  write_file_atomically((out / "fields.csv").string(), csv);
  write_file_atomically(
      (out / "fields.json").string(),
      fmt::format("{{\"axis\": \"{}\", \"kernel\": \"{}\", \"width\": {}, \"across\": {}, "
                  "\"points\": {}, \"frames\": {}, \"from\": {}, \"to\": {}, \"mass\": {}, "
                  "\"mass_integral\": {}, \"contact_integral\": [[{}, {}], [{}, {}]]}}\n",
                  name, cg_kernel_name(o.kernel), json_number(o.width), json_number(o.across),
                  o.points, frames.size(), json_number(frames.front().time),
                  json_number(frames.back().time), json_number(mass), json_number(mass_integral),
                  json_number(contact_integral(0, 0)), json_number(contact_integral(0, 1)),
                  json_number(contact_integral(1, 0)), json_number(contact_integral(1, 1))));
  Section s{"Coarse-grained fields", {}, {}, {}};
  s.summary = fmt::format(
      "Density, velocity and stress (kinetic and contact, compression positive, N/m in 2D) along "
      "{}, coarse-grained with a {} kernel of width {:.3g} m over {:.3g} m across (Weinhart et al. "
      "2012), averaged over {} snapshots from t = {:.3g} to {:.3g} s.",
      name, cg_kernel_name(o.kernel), o.width, o.across, frames.size(), frames.front().time,
      frames.back().time);
  s.numbers = {{"kernel, width", fmt::format("{}, {:.3g} m", cg_kernel_name(o.kernel), o.width)},
               {"mass: grains, integral of the density",
                fmt::format("{:.6g} kg, {:.6g} kg", mass, mass_integral)},
               {"snapshots", fmt::format("{}", frames.size())}};
  fmt::print("fields: along {}, {} kernel of width {:.3g} m, {} snapshots; mass {:.6g} kg, "
             "integral of the density {:.6g} kg\n",
             name, cg_kernel_name(o.kernel), o.width, frames.size(), mass, mass_integral);
  if (plot(out, "fields", out / "fields.csv", out / "fields.png", out / "fields.json"))
    s.charts.push_back(out / "fields.png");
  for (const auto& chart : s.charts) fmt::print("  chart: {}\n", chart.string());
  return s;
}

} // namespace talus::cli
