#include "cli/sweep/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "cli/analyze/analyses.hpp"
#include "cli/run/run3d.hpp"
#include "cli/run/scenario_source.hpp"
#include "io/checkpoint.hpp"
#include "scenario/file/load.hpp"
#include "scenario/geometry.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace talus::cli {

namespace {

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, sep)) out.push_back(part);
  if (!text.empty() && text.back() == sep) out.emplace_back();
  return out;
}

// A --vary's values: split at the commas outside brackets, so that a vector is one value
// ("[2.87,-9.38],[2.54,-9.47]": two).
std::vector<std::string> split_values(const std::string& text) {
  std::vector<std::string> out(1);
  int depth = 0;
  for (const char c : text) {
    depth += c == '[' ? 1 : c == ']' ? -1 : 0;
    if (c == ',' && depth == 0)
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

// The --set overrides of one run.
std::vector<std::string> overrides(const SweepPlan& p, const SweepRun& r) {
  std::vector<std::string> sets = p.sets;
  for (std::size_t a = 0; a < p.axes.size(); ++a) sets.push_back(p.axes[a].key + "=" + r.values[a]);
  if (p.seeds > 1 || p.axes.empty()) sets.push_back("simulation.seed=" + std::to_string(r.seed));
  return sets;
}

} // namespace

ResolvedScenario sweep_run_scenario(const SweepPlan& p, const SweepRun& r) {
  try {
    return resolve_any_scenario(p.scenario, overrides(p, r));
  } catch (const std::exception& e) {
    std::string values;
    for (const std::string& s : overrides(p, r)) values += (values.empty() ? "" : " ") + s;
    throw InvalidArgument("talus sweep: run " + r.name + " (" + values + "): " + e.what());
  }
}

namespace {

json plan_json(const SweepPlan& p) {
  json axes = json::array(), runs = json::array();
  for (const SweepAxis& a : p.axes) axes.push_back({{"key", a.key}, {"values", a.values}});
  for (const SweepRun& r : p.runs)
    runs.push_back({{"name", r.name}, {"values", r.values}, {"seed", r.seed}});
  return {{"scenario", p.scenario},     {"set", p.sets}, {"axes", axes}, {"seeds", p.seeds},
          {"first_seed", p.first_seed}, {"runs", runs}};
}

// The last row of a thermo.csv, by column name (empty when there is none).
std::map<std::string, double> last_thermo_row(const fs::path& file) {
  std::ifstream in(file);
  std::string head, line, last;
  if (!std::getline(in, head)) return {};
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  std::map<std::string, double> row;
  const auto names = split(head, ','), cells = split(last, ',');
  const std::set<std::string> kept{
      "kinetic_translational", "kinetic_rotational", "elastic",
      "coordination",          "contacts",           "packing_fraction"};
  for (std::size_t k = 0; k < std::min(names.size(), cells.size()); ++k) {
    if (!kept.count(names[k])) continue;
    try {
      row["final_" + names[k]] = std::stod(cells[k]);
    } catch (const std::exception&) {
    }
  }
  return row;
}

std::string status_of(const std::string& ended_by) {
  if (ended_by == "duration" || ended_by == "cycles") return "finished"; // cycles: frost front
  if (ended_by == "signal") return "interrupted";
  if (ended_by == "stop_at") return "stopped";
  return ended_by; // unstable, write_error
}

} // namespace

void write_plan(const fs::path& dir, const SweepPlan& p) {
  write_file_atomically((dir / "sweep.json").string(), plan_json(p).dump(2) + "\n");
}

SweepAxis parse_axis(const std::string& text) {
  const auto eq = text.find('=');
  const std::string key = eq == std::string::npos ? "" : text.substr(0, eq);
  if (key.empty() || key.find_first_of(" \t") != std::string::npos)
    throw InvalidArgument("--vary '" + text +
                          "': expected KEY=V1,V2,... (e.g. --vary "
                          "geometry.orifice=0.02,0.03)");
  if (std::count(text.begin(), text.end(), '[') != std::count(text.begin(), text.end(), ']'))
    throw InvalidArgument("--vary '" + text + "': a '[' without its ']' or a ']' without its '['");
  if (eq + 1 == text.size()) throw InvalidArgument("--vary '" + text + "': no values after '='");
  SweepAxis a{key, split_values(text.substr(eq + 1))};
  std::set<std::string> seen;
  for (const std::string& v : a.values) {
    if (v.empty())
      throw InvalidArgument("--vary '" + text + "': an empty value; expected KEY=V1,V2,...");
    if (!seen.insert(v).second)
      throw InvalidArgument("--vary '" + text + "': the value '" + v + "' is given twice");
  }
  return a;
}

SweepPlan plan_sweep(const std::string& scenario, std::vector<std::string> sets,
                     std::vector<SweepAxis> axes, std::size_t seeds) {
  if (seeds == 0) throw InvalidArgument("--seeds 0: allowed: 1 or more");
  std::set<std::string> keys;
  for (const SweepAxis& a : axes) {
    if (!keys.insert(a.key).second)
      throw InvalidArgument("--vary " + a.key + ": the key is varied twice; give its values once");
    if (a.key == "simulation.seed" && seeds > 1)
      throw InvalidArgument("--vary simulation.seed with --seeds " + std::to_string(seeds) +
                            ": vary the seed one way only");
  }
  SweepPlan p;
  p.scenario = scenario;
  p.sets = std::move(sets);
  p.axes = std::move(axes);
  p.seeds = seeds;
  p.first_seed = resolve_any_scenario(scenario, p.sets).seed;
  std::size_t total = seeds;
  for (const SweepAxis& a : p.axes) total *= a.values.size();
  const int width = std::max(3, static_cast<int>(std::to_string(total).size()));
  std::vector<std::size_t> pick(p.axes.size(), 0); // an odometer over the axes, the last fastest
  for (std::size_t n = 0; n < total;) {
    for (std::size_t k = 0; k < seeds; ++k, ++n) {
      SweepRun r;
      r.name = fmt::format("run-{:0{}}", n + 1, width);
      for (std::size_t a = 0; a < p.axes.size(); ++a) r.values.push_back(p.axes[a].values[pick[a]]);
      r.seed = p.first_seed + k;
      p.runs.push_back(r);
    }
    for (std::size_t a = p.axes.size(); a-- > 0;) {
      if (++pick[a] < p.axes[a].values.size()) break;
      pick[a] = 0;
    }
  }
  // every run's scenario must resolve; the index names the seed each run runs with (a varied
  // simulation.seed, say, rather than the scenario's)
  for (SweepRun& r : p.runs) r.seed = sweep_run_scenario(p, r).seed;
  return p;
}

bool is_sweep_folder(const fs::path& dir) {
  return fs::exists(dir / "sweep.json");
}

SweepPlan read_plan(const fs::path& dir) {
  const fs::path file = dir / "sweep.json";
  try {
    const json j = json::parse(read_file(file.string()));
    SweepPlan p;
    p.scenario = j.at("scenario").get<std::string>();
    p.sets = j.at("set").get<std::vector<std::string>>();
    for (const json& a : j.at("axes"))
      p.axes.push_back(
          {a.at("key").get<std::string>(), a.at("values").get<std::vector<std::string>>()});
    p.seeds = j.at("seeds").get<std::size_t>();
    p.first_seed = j.at("first_seed").get<std::uint64_t>();
    for (const json& r : j.at("runs"))
      p.runs.push_back({r.at("name").get<std::string>(),
                        r.at("values").get<std::vector<std::string>>(),
                        r.at("seed").get<std::uint64_t>()});
    for (const SweepRun& r : p.runs)
      if (r.values.size() != p.axes.size())
        throw InvalidArgument("a run's values do not match the axes");
    return p;
  } catch (const json::exception& e) {
    throw InvalidArgument(file.string() + ": not a sweep plan (" + e.what() + ")");
  }
}

SweepResult read_result(const fs::path& dir, const SweepRun& r) {
  const fs::path run = dir / r.name;
  SweepResult out{"pending", {}, {}};
  if (!fs::exists(run / "run.json")) return out;
  try {
    const json j = json::parse(read_file((run / "run.json").string()));
    out.status = status_of(j.at("ended_by").get<std::string>());
    for (const char* key : {"time", "steps", "wall_seconds", "particles"})
      out.numbers[key] = j.at(key).get<double>();
  } catch (const json::exception& e) {
    out.status = "failed";
    out.texts["error"] = std::string("run.json: ") + e.what();
    return out;
  }
  for (const auto& [k, v] : last_thermo_row(run / "thermo.csv")) out.numbers[k] = v;
  if (out.status != "finished") return out;
  try {
    if (is_3d_run_folder(run)) return out; // spheres: no orifice in 3D yet
    RunData data{run};
    if (has_orifice(data.scenario().geometry) && data.has_snapshots()) {
      const Discharge q = run_discharge(data, {});
      out.texts["discharge_end"] = to_string(q.end);
      out.numbers["passed"] = static_cast<double>(q.passed);
      if (q.why_no_rate.empty()) {
        out.numbers["rate"] = q.rate;
        out.numbers["rate_error"] = q.rate_error;
        out.numbers["window_from"] = q.window_from;
        out.numbers["window_to"] = q.window_to;
      } else {
        out.texts["why_no_rate"] = q.why_no_rate;
      }
    }
  } catch (const InvalidArgument& e) {
    out.texts["why_no_rate"] = e.what();
  }
  return out;
}

void write_index(const fs::path& dir, const SweepPlan& plan,
                 const std::vector<SweepResult>& results) {
  std::set<std::string> numbers, texts;
  for (const SweepResult& r : results) {
    for (const auto& [k, _] : r.numbers) numbers.insert(k);
    for (const auto& [k, _] : r.texts) texts.insert(k);
  }
  std::string csv = "run";
  for (const SweepAxis& a : plan.axes) csv += "," + a.key;
  csv += ",seed,status";
  for (const auto& k : numbers) csv += "," + k;
  for (const auto& k : texts) csv += "," + k;
  csv += "\n";
  json runs = json::array();
  for (std::size_t i = 0; i < plan.runs.size(); ++i) {
    const SweepRun& run = plan.runs[i];
    const SweepResult& r = results[i];
    json values = json::object(), res = json::object();
    csv += run.name;
    for (std::size_t a = 0; a < plan.axes.size(); ++a) {
      csv.push_back(',');
      csv.append(csv_cell(run.values[a]));
      values[plan.axes[a].key] = run.values[a];
    }
    csv += fmt::format(",{},{}", run.seed, r.status);
    for (const auto& k : numbers) {
      const auto it = r.numbers.find(k);
      csv.push_back(',');
      if (it != r.numbers.end()) csv.append(csv_number(it->second));
      if (it != r.numbers.end() && std::isfinite(it->second)) res[k] = it->second;
    }
    for (const auto& k : texts) {
      const auto it = r.texts.find(k);
      std::string cell = it == r.texts.end() ? "" : it->second;
      if (it != r.texts.end()) res[k] = it->second;
      csv.push_back(',');
      csv.append(csv_cell(cell));
    }
    csv += "\n";
    runs.push_back({{"run", run.name},
                    {"values", values},
                    {"seed", run.seed},
                    {"status", r.status},
                    {"results", res}});
  }
  json axes = json::array();
  for (const SweepAxis& a : plan.axes) axes.push_back(a.key);
  write_file_atomically((dir / "index.csv").string(), csv);
  write_file_atomically((dir / "index.json").string(),
                        json{{"scenario", plan.scenario}, {"axes", axes}, {"runs", runs}}.dump(2) +
                            "\n");
}

} // namespace talus::cli
