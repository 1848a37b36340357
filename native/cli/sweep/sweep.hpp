#pragma once
// A parameter sweep: the product of the values of the varied keys and the seeds, each a run in
// its own run folder under one sweep folder. The plan is fixed when the sweep starts
// (sweep.json, and each run's resolved scenario in scenarios/); running it, or continuing it,
// runs the unfinished runs as child processes (`talus run` or `talus resume`), at most `jobs` at
// a time, and keeps an index of every run's values and key results (index.csv, index.json).
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "cli/run/scenario_source.hpp"

namespace talus::cli {

struct SweepAxis {
  std::string key;                 ///< a scenario key, as --set takes it
  std::vector<std::string> values; ///< as the user wrote them
};

struct SweepRun {
  std::string name;                ///< its folder under the sweep folder: run-001, ...
  std::vector<std::string> values; ///< one per axis
  std::uint64_t seed = 0;          ///< simulation.seed
};

struct SweepPlan {
  std::string scenario;          ///< as given on the command line
  std::vector<std::string> sets; ///< --set overrides that every run shares
  std::vector<SweepAxis> axes;
  std::size_t seeds = 1;
  std::uint64_t first_seed = 0;
  std::vector<SweepRun> runs;
};

/// Parses "KEY=V1,V2,..." (a --vary argument). Throws InvalidArgument naming the argument.
SweepAxis parse_axis(const std::string& text);

/// The plan for `scenario` with the shared overrides, the axes and the seeds: every run's
/// scenario is resolved here, so a bad key or value stops the sweep before anything runs.
/// Writes nothing.
SweepPlan plan_sweep(const std::string& scenario, std::vector<std::string> sets,
                     std::vector<SweepAxis> axes, std::size_t seeds);

/// The resolved scenario of run `r`: the plan's scenario (2D or 3D) with the run's values and
/// seed. Throws InvalidArgument naming the run and its values when it does not resolve.
ResolvedScenario sweep_run_scenario(const SweepPlan& p, const SweepRun& r);

/// Writes dir/sweep.json.
void write_plan(const std::filesystem::path& dir, const SweepPlan& p);

/// Whether `dir` holds a sweep (a sweep.json).
bool is_sweep_folder(const std::filesystem::path& dir);

/// Reads dir/sweep.json. Throws InvalidArgument when it is missing or malformed.
SweepPlan read_plan(const std::filesystem::path& dir);

/// One run's row of the index: its values, its state and its key results.
struct SweepResult {
  std::string status; ///< finished, pending, interrupted, stopped, unstable, write_error, failed
  std::map<std::string, double> numbers;    ///< key results (time, steps, rate, ...)
  std::map<std::string, std::string> texts; ///< discharge end, why no rate
};

/// Reads what run `r`'s folder holds now: its run.json, the last thermo row and, for a
/// container with an orifice, the discharge.
SweepResult read_result(const std::filesystem::path& dir, const SweepRun& r);

/// Writes dir/index.csv and dir/index.json for the plan and results (one per run).
void write_index(const std::filesystem::path& dir, const SweepPlan& plan,
                 const std::vector<SweepResult>& results);

struct SweepOptions {
  unsigned jobs = 0; ///< runs at a time (0: one per core)
  bool quiet = false;
};

/// Starts a sweep in `dir` (new or empty), or with `resume`, continues the one there. Returns
/// 0 when every run finished, 130 when stopped by a signal (continue with talus resume DIR), 1
/// when a run failed.
int run_sweep(const std::filesystem::path& dir, const SweepPlan* plan, const SweepOptions& o);

} // namespace talus::cli
