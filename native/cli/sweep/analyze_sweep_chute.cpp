// `talus analyze SWEEP chute`: layers of several depths on one slope or several, each flowing or
// come to a stop by the run's end, and on each slope the depth h_stop between the two (Pouliquen
// 1999).
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

// The layers on one slope and the depth h_stop between those that stopped and those that flowed.
struct Slope {
  double angle = 0.0; ///< rad
  double deepest_stopped = -1.0, shallowest_flowing = std::numeric_limits<double>::infinity();
  bool some_stopped() const { return deepest_stopped > 0.0; }
  bool some_flowing() const { return std::isfinite(shallowest_flowing); }
  bool bracketed() const { return some_stopped() && some_flowing(); }
  bool sharp() const { return bracketed() && deepest_stopped < shallowest_flowing; }
  double lo() const { return std::min(deepest_stopped, shallowest_flowing); }
  double hi() const { return std::max(deepest_stopped, shallowest_flowing); }
};

Slope& slope_of(std::vector<Slope>& slopes, double angle) {
  for (Slope& s : slopes)
    if (std::abs(s.angle - angle) < 1e-9) return s;
  return slopes.emplace_back(Slope{.angle = angle});
}

json slope_json(const Slope& s) {
  json j{{"angle_deg", s.angle * 180.0 / M_PI}};
  j["deepest_stopped"] = s.some_stopped() ? json(s.deepest_stopped) : json(nullptr);
  j["shallowest_flowing"] = s.some_flowing() ? json(s.shallowest_flowing) : json(nullptr);
  // h_stop between the two kinds of layer; near it whether a layer stops is a matter of chance
  // (of its grains' arrangement as it slows), so a deeper layer may stop where a shallower one
  // flowed: then h_stop lies in the band where both happened
  j["bracketed"] = s.bracketed();
  j["sharp"] = s.sharp();
  j["h_stop_lo"] = s.bracketed() ? json(s.lo()) : json(nullptr);
  j["h_stop_hi"] = s.bracketed() ? json(s.hi()) : json(nullptr);
  return j;
}

void print_slope(const Slope& s, double diameter) {
  const double deg = s.angle * 180.0 / M_PI;
  if (!s.some_stopped())
    fmt::print("  h_stop at {:.2f} deg: every layer flows: below {:.2f} d\n", deg,
               s.shallowest_flowing / diameter);
  else if (!s.some_flowing())
    fmt::print("  h_stop at {:.2f} deg: every layer stopped: above {:.2f} d\n", deg,
               s.deepest_stopped / diameter);
  else if (s.sharp())
    fmt::print("  h_stop at {:.2f} deg: between {:.2f} and {:.2f} d ({:.4g} to {:.4g} m)\n", deg,
               s.lo() / diameter, s.hi() / diameter, s.lo(), s.hi());
  else
    fmt::print("  h_stop at {:.2f} deg: from {:.2f} to {:.2f} d ({:.4g} to {:.4g} m): layers in "
               "this band both stopped and flowed (near h_stop a layer stops by chance: more "
               "seeds narrow it)\n",
               deg, s.lo() / diameter, s.hi() / diameter, s.lo(), s.hi());
}

} // namespace

void analyze_sweep_chute(const fs::path& dir, const AnalysisOptions& o) {
  const SweepPlan plan = read_plan(dir);
  std::string csv = "run,";
  for (const SweepAxis& a : plan.axes) csv += csv_cell(a.key) + ",";
  csv += "seed,angle_deg,depth,depth_over_d,mean_velocity,flowing\n";
  std::vector<Slope> slopes;
  double diameter = NAN;
  std::size_t analysed = 0;
  for (const SweepRun& r : plan.runs) {
    if (!fs::exists(dir / r.name / "run.json")) continue; // not run yet
    RunData data{dir / r.name};
    const LayerEnd e = layer_end(data, o);
    if (analysed++ == 0) diameter = e.diameter;
    csv += r.name + ",";
    for (const auto& v : r.values) csv += csv_cell(v) + ",";
    csv += fmt::format("{},{:.4f},{:.6g},{:.4f},{:.6g},{}\n", r.seed, e.angle * 180.0 / M_PI,
                       e.depth, e.depth / e.diameter, e.velocity, e.flowing ? 1 : 0);
    fmt::print("{}: {:.2f} d deep at {:.2f} deg: {} (mean {:.4g} m/s down the slope)\n", r.name,
               e.depth / e.diameter, e.angle * 180.0 / M_PI, e.flowing ? "flowing" : "stopped",
               e.velocity);
    Slope& s = slope_of(slopes, e.angle);
    if (e.flowing)
      s.shallowest_flowing = std::min(s.shallowest_flowing, e.depth);
    else
      s.deepest_stopped = std::max(s.deepest_stopped, e.depth);
  }
  if (analysed == 0)
    throw InvalidArgument("no run of the sweep in '" + dir.string() + "' has run yet");
  std::sort(slopes.begin(), slopes.end(),
            [](const Slope& a, const Slope& b) { return a.angle < b.angle; });
  // one slope: its figures at the top level too, as before slopes were swept
  json meta = slopes.size() == 1 ? slope_json(slopes[0]) : json::object();
  meta["diameter"] = diameter;
  meta["runs"] = analysed;
  meta["slopes"] = json::array();
  for (const Slope& s : slopes) {
    meta["slopes"].push_back(slope_json(s));
    print_slope(s, diameter);
  }
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
