// `talus sweep SCENARIO --vary KEY=V1,V2 ... [--seeds N]`: a parameter sweep (cli/sweep.hpp).
#include <memory>

#include <fmt/core.h>

#include "cli/commands.hpp"
#include "cli/run/scenario_source.hpp"
#include "cli/sweep/sweep.hpp"

namespace talus::cli {

void add_sweep_command(CLI::App& app) {
  struct Options {
    std::string scenario, out;
    std::vector<std::string> vary, set;
    std::size_t seeds = 1;
    SweepOptions run;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "sweep", "run a scenario over the product of the varied keys' values and seeds, each run in "
               "its own folder under one sweep folder, several at a time; continue a stopped "
               "sweep with talus resume DIR, gather it with talus analyze DIR");
  cmd->add_option("scenario", o->scenario, "scenario file or built-in name")->required();
  cmd->add_option("--vary", o->vary,
                  "KEY=V1,V2,...: a key and its values, e.g. --vary geometry.orifice=0.02,0.03 "
                  "(repeatable: the runs are the product)");
  cmd->add_option("--set", o->set,
                  "override a key in every run, e.g. --set particles.count=500 (repeatable)");
  cmd->add_option("--seeds", o->seeds,
                  "runs per combination, with simulation.seed = the scenario's seed + 0, 1, ...")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{1}, std::size_t{100000}));
  cmd->add_option("--out", o->out, "sweep folder (default: runs/sweep-<scenario name>)");
  cmd->add_option("--jobs", o->run.jobs, "runs at a time, one thread each (0: one per core)")
      ->capture_default_str()
      ->check(CLI::Range(0u, 4096u));
  cmd->add_flag("--quiet", o->run.quiet, "no progress lines");
  cmd->callback([o] {
    std::vector<SweepAxis> axes;
    for (const std::string& v : o->vary) axes.push_back(parse_axis(v));
    if (axes.empty() && o->seeds < 2)
      throw InvalidArgument("talus sweep: nothing varies; give --vary KEY=V1,V2,... or --seeds N "
                            "with N >= 2");
    const SweepPlan plan = plan_sweep(o->scenario, o->set, std::move(axes), o->seeds);
    const std::string dir =
        o->out.empty() ? "runs/sweep-" + resolve_any_scenario(o->scenario, o->set).name : o->out;
    exit_status() = run_sweep(dir, &plan, o->run);
  });
}

} // namespace talus::cli
