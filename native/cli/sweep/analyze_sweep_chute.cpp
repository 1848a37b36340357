// `talus analyze SWEEP chute`: layers of several depths on one slope, each flowing or come to a
// stop by the run's end, and the depth h_stop between the two (Pouliquen 1999).
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "cli/sweep/analyze_sweep.hpp"
#include "cli/sweep/sweep.hpp"
#include "io/checkpoint.hpp"
#include "post/chute.hpp"
#include "scenario/file/load.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace talus::cli {

namespace {

// How long before a run's end its state is judged: the mean over the last snapshots of this span.
constexpr double judged_over = 2.0; // s
// A layer whose grains move down the slope slower than this times sqrt(g d) on average has
// stopped: a flowing layer moves at a good fraction of sqrt(g d) (I of 0.01 and more), a stopped
// one only creeps and rattles.
constexpr double stopped_speed = 0.01;

struct LayerEnd {
  double depth = 0.0, velocity = 0.0, angle = 0.0, diameter = 0.0;
  bool flowing = false;
};

// The gravity in force at the run's end: the scenario's with every stage's changes made.
Vec2 final_gravity(const Scenario& s) {
  std::vector<std::string> sets;
  for (const StageSection& st : s.stages) sets.insert(sets.end(), st.set.begin(), st.set.end());
  return load_scenario(to_toml(s), "scenario.toml", sets).simulation.gravity;
}

LayerEnd layer_end(RunData& run, const AnalysisOptions& a) {
  const Scenario& s = run.scenario();
  if (s.geometry.periodic != "x")
    throw InvalidArgument("chute: needs layers periodic along x on a base of wall grains (the "
                          "built-in chute_stop); " +
                          run.dir().string() + " is not periodic in x");
  ChuteOptions o;
  o.kernel = parse_cg_kernel(a.kernel);
  o.width = kernel_width(run, a);
  o.across = s.geometry.box->hi.x - s.geometry.box->lo.x;
  o.gravity = final_gravity(s);
  const std::vector<Frame>& all = run.frames(0.0);
  const std::vector<Frame> frames =
      run.frames_with_contacts(a.from >= 0.0 ? a.from : all.back().time - judged_over);
  const ChuteFlow c = chute_flow(frames, o);
  if (c.depth <= 0.0) throw InvalidArgument("chute: " + run.dir().string() + ": " + c.why_not);
  LayerEnd e;
  e.depth = c.depth, e.angle = c.angle, e.diameter = c.diameter;
  const double sign = o.gravity.x > 0.0 ? 1.0 : -1.0;
  std::size_t n = 0;
  for (const Frame& f : frames)
    for (std::size_t i = 0; i < f.position.size(); ++i)
      if (f.kind[i] == 0) e.velocity += sign * f.velocity[i].x, ++n;
  e.velocity /= static_cast<double>(std::max<std::size_t>(n, 1));
  e.flowing = e.velocity > stopped_speed * std::sqrt(norm(o.gravity) * c.diameter);
  return e;
}

} // namespace

void analyze_sweep_chute(const fs::path& dir, const AnalysisOptions& o) {
  const SweepPlan plan = read_plan(dir);
  std::string csv = "run,";
  for (const SweepAxis& a : plan.axes) csv += a.key + ",";
  csv += "seed,angle_deg,depth,depth_over_d,mean_velocity,flowing\n";
  double deepest_stopped = -1.0, shallowest_flowing = std::numeric_limits<double>::infinity();
  double angle = NAN, diameter = NAN;
  std::size_t analysed = 0;
  bool one_angle = true;
  for (const SweepRun& r : plan.runs) {
    if (!fs::exists(dir / r.name / "run.json")) continue; // not run yet
    RunData data{dir / r.name};
    const LayerEnd e = layer_end(data, o);
    if (analysed++ == 0) angle = e.angle, diameter = e.diameter;
    one_angle = one_angle && std::abs(e.angle - angle) < 1e-9;
    csv += r.name + ",";
    for (const auto& v : r.values) csv += v + ",";
    csv += fmt::format("{},{:.4f},{:.6g},{:.4f},{:.6g},{}\n", r.seed, e.angle * 180.0 / M_PI,
                       e.depth, e.depth / e.diameter, e.velocity, e.flowing ? 1 : 0);
    fmt::print("{}: {:.2f} d deep at {:.2f} deg: {} (mean {:.4g} m/s down the slope)\n", r.name,
               e.depth / e.diameter, e.angle * 180.0 / M_PI, e.flowing ? "flowing" : "stopped",
               e.velocity);
    if (e.flowing)
      shallowest_flowing = std::min(shallowest_flowing, e.depth);
    else
      deepest_stopped = std::max(deepest_stopped, e.depth);
  }
  if (analysed == 0)
    throw InvalidArgument("no run of the sweep in '" + dir.string() + "' has run yet");
  if (!one_angle)
    throw InvalidArgument("chute: the runs end on different slopes; h_stop is a depth on one "
                          "slope (sweep the depth, particles.count, at one angle)");
  json meta{{"angle_deg", angle * 180.0 / M_PI}, {"diameter", diameter}, {"runs", analysed}};
  const bool some_stopped = deepest_stopped > 0.0, some_flowing = std::isfinite(shallowest_flowing);
  meta["deepest_stopped"] = some_stopped ? json(deepest_stopped) : json(nullptr);
  meta["shallowest_flowing"] = some_flowing ? json(shallowest_flowing) : json(nullptr);
  // h_stop between the two kinds of layer; near it whether a layer stops is a matter of chance
  // (of its grains' arrangement as it slows), so a deeper layer may stop where a shallower one
  // flowed: then h_stop lies in the band where both happened
  meta["bracketed"] = some_stopped && some_flowing;
  meta["sharp"] = some_stopped && some_flowing && deepest_stopped < shallowest_flowing;
  const double lo = std::min(deepest_stopped, shallowest_flowing);
  const double hi = std::max(deepest_stopped, shallowest_flowing);
  meta["h_stop_lo"] = meta["bracketed"].get<bool>() ? json(lo) : json(nullptr);
  meta["h_stop_hi"] = meta["bracketed"].get<bool>() ? json(hi) : json(nullptr);
  const double deg = angle * 180.0 / M_PI;
  if (!some_stopped)
    fmt::print("  h_stop at {:.2f} deg: every layer flows: below {:.2f} d\n", deg,
               shallowest_flowing / diameter);
  else if (!some_flowing)
    fmt::print("  h_stop at {:.2f} deg: every layer stopped: above {:.2f} d\n", deg,
               deepest_stopped / diameter);
  else if (meta["sharp"].get<bool>())
    fmt::print("  h_stop at {:.2f} deg: between {:.2f} and {:.2f} d ({:.4g} to {:.4g} m)\n", deg,
               lo / diameter, hi / diameter, lo, hi);
  else
    fmt::print("  h_stop at {:.2f} deg: from {:.2f} to {:.2f} d ({:.4g} to {:.4g} m): layers in "
               "this band both stopped and flowed (near h_stop a layer stops by chance: more "
               "seeds narrow it)\n",
               deg, lo / diameter, hi / diameter, lo, hi);
  const fs::path out = dir / "analysis";
  fs::create_directories(out);
  write_file_atomically((out / "chute_stop.csv").string(), csv);
  write_file_atomically((out / "chute_stop.json").string(), meta.dump(2) + "\n");
  fmt::print("  layers: {}\n", (out / "chute_stop.csv").string());
  if (plot(out, "chute_stop", out / "chute_stop.csv", out / "chute_stop.png",
           out / "chute_stop.json"))
    fmt::print("  chart: {}\n", (out / "chute_stop.png").string());
}

} // namespace talus::cli
