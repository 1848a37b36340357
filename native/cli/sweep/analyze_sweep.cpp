// `talus analyze SWEEP [RESULT]`: a sweep's result against its varied keys, with the spread over
// seeds; `talus analyze SWEEP discharge`: every run's discharge and the Beverloo fit over the
// orifice widths.
#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "cli/analyze/analyses.hpp"
#include "cli/sweep/analyze_sweep.hpp"
#include "cli/sweep/sweep.hpp"
#include "io/checkpoint.hpp"
#include "post/beverloo.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace talus::cli {

namespace {

// The runs' values with the seed left out: one group per combination, in the plan's order.
struct Group {
  std::vector<std::string> values;
  std::vector<std::size_t> runs; // indices into the plan
};

std::vector<Group> groups_of(const SweepPlan& p, std::size_t leave_out = SIZE_MAX) {
  std::vector<Group> out;
  for (std::size_t i = 0; i < p.runs.size(); ++i) {
    std::vector<std::string> v;
    for (std::size_t a = 0; a < p.axes.size(); ++a)
      if (a != leave_out) v.push_back(p.runs[i].values[a]);
    auto it = std::find_if(out.begin(), out.end(), [&](const Group& g) { return g.values == v; });
    if (it == out.end()) out.push_back({v, {}}), it = out.end() - 1;
    it->runs.push_back(i);
  }
  return out;
}

struct Spread {
  std::size_t n = 0;
  double mean = NAN, sd = NAN, min = NAN, max = NAN;
};

Spread spread(const std::vector<double>& x) {
  Spread s;
  s.n = x.size();
  if (x.empty()) return s;
  s.mean = 0.0;
  for (const double v : x) s.mean += v / static_cast<double>(x.size());
  s.min = *std::min_element(x.begin(), x.end()), s.max = *std::max_element(x.begin(), x.end());
  if (x.size() > 1) {
    double var = 0.0;
    for (const double v : x) var += (v - s.mean) * (v - s.mean);
    s.sd = std::sqrt(var / static_cast<double>(x.size() - 1));
  }
  return s;
}

json read_index(const fs::path& dir) {
  const fs::path file = dir / "index.json";
  if (!fs::exists(file))
    throw InvalidArgument(file.string() + " is missing: the sweep has not started");
  return json::parse(read_file(file.string()));
}

std::string header(const SweepPlan& p) {
  std::string h;
  for (const SweepAxis& a : p.axes) h += a.key + ",";
  return h;
}

} // namespace

void analyze_sweep_result(const fs::path& dir, const std::string& result) {
  const SweepPlan plan = read_plan(dir);
  const json index = read_index(dir);
  std::vector<std::string> names;
  for (const json& r : index.at("runs"))
    for (const auto& [k, v] : r.at("results").items())
      if (v.is_number() && std::find(names.begin(), names.end(), k) == names.end())
        names.push_back(k);
  if (std::find(names.begin(), names.end(), result) == names.end()) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    throw InvalidArgument("the sweep in '" + dir.string() + "' has no result '" + result +
                          "'; its results: " + (list.empty() ? "(none yet)" : list) +
                          ", or discharge");
  }
  const fs::path out = dir / "analysis";
  fs::create_directories(out);
  std::string csv = header(plan) + "runs,mean,sd,min,max\n";
  for (const Group& g : groups_of(plan)) {
    std::vector<double> x;
    for (const std::size_t i : g.runs) {
      const json& res = index.at("runs").at(i).at("results");
      if (res.contains(result) && index.at("runs").at(i).at("status") == "finished")
        x.push_back(res.at(result).get<double>());
    }
    const Spread s = spread(x);
    for (const auto& v : g.values) csv += v + ",";
    csv += fmt::format("{},{},{},{},{}\n", s.n, csv_number(s.mean), csv_number(s.sd),
                       csv_number(s.min), csv_number(s.max));
  }
  const fs::path table = out / (result + ".csv");
  write_file_atomically(table.string(), csv);
  json meta{{"result", result}, {"axes", json::array()}, {"seeds", plan.seeds}};
  for (const SweepAxis& a : plan.axes) meta["axes"].push_back(a.key);
  write_file_atomically((out / (result + ".json")).string(), meta.dump() + "\n");
  fmt::print("{}: {} combinations over {} runs: {}\n", result, groups_of(plan).size(),
             plan.runs.size(), table.string());
  const fs::path png = out / (result + ".png");
  if (plot(out, "sweep", table, png, out / (result + ".json")))
    fmt::print("  chart: {}\n", png.string());
}

namespace {

json fit_json(const BeverlooFit& f) {
  if (!f.ok) return {{"ok", false}, {"why_not", f.why_not}};
  return {{"ok", true},           {"A", f.A},     {"A_error", f.A_error}, {"k", f.k},
          {"k_error", f.k_error}, {"n", f.n},     {"n_error", f.n_error}, {"C", f.C},
          {"C_error", f.C_error}, {"rms", f.rms}, {"points", f.points},   {"n_fixed", f.n_fixed}};
}

std::string fit_text(const BeverlooFit& f) {
  if (!f.ok) return "no fit: " + f.why_not;
  std::string n = f.n_fixed ? fmt::format("n = {:.4g} (fixed)", f.n)
                            : fmt::format("n = {:.3f} +- {:.3f}", f.n, f.n_error);
  return fmt::format("W = A (D/d - k)^n: A = {:.4g} +- {:.2g} grains/s, k = {:.3f} +- {:.3f}, {}; "
                     "rms residual {:.3g} grains/s over {} runs",
                     f.A, f.A_error, f.k, f.k_error, n, f.rms, f.points);
}

// Beverloo's law fitted to one group of runs (the same values but the orifice's, axis a), with
// n free and n = 3/2; printed, and returned for beverloo.json.
json fit_group(const SweepPlan& plan, const Group& g, std::size_t a,
               const std::vector<double>& rate, double diameter) {
  std::vector<double> D, W;
  std::size_t without = 0;
  for (const std::size_t i : g.runs) {
    const double width = std::stod(plan.runs[i].values[a]);
    if (!std::isfinite(rate[i])) {
      ++without;
      continue;
    }
    D.push_back(width), W.push_back(rate[i]);
  }
  const BeverlooFit free = fit_beverloo(D, W, diameter), fixed = fit_beverloo(D, W, diameter, 1.5);
  std::string label;
  for (std::size_t k = 0, j = 0; k < plan.axes.size(); ++k)
    if (k != a) label += (label.empty() ? "" : ", ") + plan.axes[k].key + "=" + g.values[j++];
  fmt::print("  Beverloo{}{}: {}\n  n = 3/2: {}\n", label.empty() ? "" : " at ", label,
             fit_text(free), fit_text(fixed));
  if (without > 0)
    fmt::print("  ({} runs without a rate left out: clogged, or too few grains)\n", without);
  return {{"values", g.values},
          {"label", label},
          {"runs_without_rate", without},
          {"free", fit_json(free)},
          {"fixed", fit_json(fixed)}};
}

} // namespace

void analyze_sweep_discharge(const fs::path& dir, const AnalysisOptions& o) {
  const SweepPlan plan = read_plan(dir);
  const fs::path out = dir / "analysis";
  std::string csv =
      "run," + header(plan) + "seed,end,passed,rate,rate_error,window_from,window_to\n";
  std::vector<double> rate(plan.runs.size(), NAN), error(plan.runs.size(), NAN);
  std::vector<std::string> end(plan.runs.size()); // empty: not run yet
  double diameter = NAN;
  std::size_t analysed = 0;
  for (std::size_t i = 0; i < plan.runs.size(); ++i) {
    const SweepRun& r = plan.runs[i];
    const fs::path run = dir / r.name;
    if (!fs::exists(run / "run.json")) continue; // not run yet
    RunData data{run};
    const Discharge q = run_discharge(data, o);
    if (std::isnan(diameter)) diameter = 2.0 * data.mean_radius();
    ++analysed;
    rate[i] = q.rate, error[i] = q.rate_error, end[i] = to_string(q.end);
    csv += r.name + ",";
    for (const auto& v : r.values) csv += csv_cell(v) + ",";
    csv += fmt::format("{},{},{},{},{},{},{}\n", r.seed, to_string(q.end), q.passed,
                       csv_number(q.rate), csv_number(q.rate_error), csv_number(q.window_from),
                       csv_number(q.window_to));
    fmt::print("{}: {}\n", r.name, discharge_text(q));
  }
  if (analysed == 0)
    throw InvalidArgument("no run of the sweep in '" + dir.string() + "' has run yet");
  fs::create_directories(out);
  write_file_atomically((out / "discharge.csv").string(), csv);
  fmt::print("discharge of {} runs: {}\n", analysed, (out / "discharge.csv").string());

  const auto axis = std::find_if(plan.axes.begin(), plan.axes.end(),
                                 [](const SweepAxis& a) { return a.key == "geometry.orifice"; });
  if (axis == plan.axes.end()) {
    fmt::print("  (no Beverloo fit: the sweep does not vary geometry.orifice)\n");
    return;
  }
  const auto a = static_cast<std::size_t>(axis - plan.axes.begin());
  json fits = json::array();
  std::string points = header(plan) + "run,seed,end,D,D_over_d,rate,rate_error\n";
  for (const Group& g : groups_of(plan, a)) fits.push_back(fit_group(plan, g, a, rate, diameter));
  for (std::size_t i = 0; i < plan.runs.size(); ++i) { // a run without a rate: its end only
    if (end[i].empty()) continue;
    for (std::size_t k = 0; k < plan.axes.size(); ++k) points += plan.runs[i].values[k] + ",";
    const double width = std::stod(plan.runs[i].values[a]);
    points += fmt::format("{},{},{},{},{},{},{}\n", plan.runs[i].name, plan.runs[i].seed, end[i],
                          width, width / diameter, csv_number(rate[i]), csv_number(error[i]));
  }
  json axes = json::array();
  for (const SweepAxis& x : plan.axes) axes.push_back(x.key);
  const json meta{{"d", diameter}, {"orifice_axis", axis->key}, {"axes", axes}, {"fits", fits}};
  write_file_atomically((out / "beverloo.csv").string(), points);
  write_file_atomically((out / "beverloo.json").string(), meta.dump(2) + "\n");
  fmt::print("  fit: {}\n", (out / "beverloo.json").string());
  if (plot(out, "beverloo", out / "beverloo.csv", out / "beverloo.png", out / "beverloo.json"))
    fmt::print("  chart: {}\n", (out / "beverloo.png").string());
}

} // namespace talus::cli
