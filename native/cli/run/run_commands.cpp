// `talus run`, `talus resume`, `talus scenarios` and `talus convert`.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

#include <fmt/core.h>

#include "cli/builtin_scenarios.hpp"
#include "cli/commands.hpp"
#include "cli/run/run3d.hpp"
#include "cli/run/run3d_session.hpp"
#include "cli/run/run_loop.hpp"
#include "cli/run/scenario_source.hpp"
#include "cli/sweep/sweep.hpp"
#include "io/checkpoint.hpp"
#include "io/thesis_format.hpp"
#include "scenario/file/load.hpp"
#include "scenario/file/load3.hpp"
#include "scenario/timestep_accuracy.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

int& exit_status() {
  static int status = 0;
  return status;
}

namespace {

// --stop-at: a finite time >= 0 s (CLI11's NonNegativeNumber lets NaN through).
const CLI::Validator stop_time(
    [](const std::string& text) -> std::string {
      try {
        std::size_t used = 0;
        const double t = std::stod(text, &used);
        if (used == text.size() && std::isfinite(t) && t >= 0.0) return {};
      } catch (const std::exception&) {
      }
      return text + ": allowed: a finite time >= 0 s";
    },
    "TIME >= 0");

std::string describe(std::string_view toml_text) {
  try {
    const toml::table t = toml::parse(toml_text);
    return t["description"].value_or(std::string{});
  } catch (...) {
    return {};
  }
}

} // namespace

void add_run_command(CLI::App& app) {
  struct Options {
    std::string scenario, out;
    std::vector<std::string> set;
    RunOptions run;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("run", "run a scenario: a .toml file, a thesis .in file, or a "
                                            "built-in scenario's name (see `talus scenarios`)");
  cmd->add_option("scenario", o->scenario, "scenario file or built-in name")->required();
  cmd->add_option("--out", o->out,
                  "run folder (default: runs/<scenario name>); must be new or empty");
  cmd->add_option("--set", o->set, "override a key, e.g. --set particles.count=5000 (repeatable)");
  cmd->add_option("--threads", o->run.threads, "threads (0: all cores; default: the scenario's)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--stop-at", o->run.stop_at,
                  "stop at this simulated time (s) after a checkpoint; continue with talus resume")
      ->check(stop_time);
  cmd->add_flag("--quiet", o->run.quiet, "no progress output");
  cmd->callback([o] {
    const ScenarioText text = scenario_text(o->scenario);
    if (scenario_dimension(text, o->set) == 3) {
      const Scenario3 s = load_scenario3(text.text, text.file, o->set);
      exit_status() = run_3d(s, o->out.empty() ? "runs/" + s.name : o->out, o->run, o->scenario);
      return;
    }
    const Scenario s = load_scenario(text.text, text.file, o->set);
    const std::string dir = o->out.empty() ? "runs/" + s.name : o->out;
    // the folder and its lock before the settling, which can take minutes
    RunFolder folder = RunFolder::create(dir, s);
    if (!o->run.quiet)
      fmt::print("talus run {}: {}\n", s.name,
                 s.description.empty() ? "(no description)" : s.description);
    exit_status() = settle_and_start(s, std::move(folder), o->run, o->scenario);
  });
}

void add_resume_command(CLI::App& app) {
  auto dir = std::make_shared<std::string>();
  auto o = std::make_shared<RunOptions>();
  auto sweep = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand(
      "resume", "continue a stopped run from its last checkpoint (bit-identical to an "
                "uninterrupted run), or a stopped sweep with the runs it has not finished");
  cmd->add_option("dir", *dir, "the run folder or sweep folder")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--jobs", sweep->jobs, "a sweep: runs at a time (0: one per core)")
      ->check(CLI::Range(0u, 4096u));
  cmd->add_option("--threads", o->threads, "threads (0: all cores)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--stop-at", o->stop_at, "stop again at this simulated time (s)")
      ->check(stop_time);
  cmd->add_option("--set", o->set,
                  "change a key from the resume point on, e.g. --set simulation.gravity=[0,-5] "
                  "(repeatable; the keys a run can change: docs/scenarios.md, \"Runs in stages\")");
  cmd->add_option("--duration", o->duration,
                  "the run's whole length (s) from now on: a finished run goes on to it")
      ->check(stop_time);
  cmd->add_flag("--quiet", o->quiet, "no progress output");
  cmd->callback([dir, o, sweep] {
    if (is_sweep_folder(*dir)) {
      if (!o->set.empty() || o->duration >= 0.0)
        throw InvalidArgument("--set and --duration change one run; '" + *dir +
                              "' is a sweep folder");
      sweep->quiet = o->quiet;
      exit_status() = run_sweep(*dir, nullptr, *sweep);
    } else {
      if (is_3d_run_folder(*dir)) {
        exit_status() = resume_3d(RunFolder::open(*dir), *o);
        return;
      }
      exit_status() = resume_run(*dir, *o);
    }
  });
}

void add_scenarios_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("scenarios", "list the built-in scenarios");
  cmd->callback([] {
    for (const auto& b : builtin_scenarios()) fmt::print("{:<14} {}\n", b.name, describe(b.text));
  });
}

void add_checkpoint_command(CLI::App& app) {
  auto dir = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "checkpoint", "describe a run folder's last checkpoint: time, step, particles, state hash "
                    "(two runs with the same hash have bit-identical states)");
  cmd->add_option("dir", *dir, "the run folder")->required()->check(CLI::ExistingDirectory);
  cmd->callback([dir] {
    // the checkpoint talus resume would continue from
    const fs::path d(*dir);
    refuse_3d_run_folder(d, "checkpoint");
    const auto [c, book] = checkpoint_to_resume(d, read_file((d / "scenario.toml").string()));
    const Particles& p = c.state.world.particles;
    std::uint64_t h = 1469598103934665603ULL;
    const auto mix = [&h](const void* data, std::size_t bytes) {
      const auto* b = static_cast<const unsigned char*>(data);
      for (std::size_t k = 0; k < bytes; ++k) h = (h ^ b[k]) * 1099511628211ULL;
    };
    mix(p.position.data(), p.size() * sizeof(Vec2));
    mix(p.velocity.data(), p.size() * sizeof(Vec2));
    mix(p.angle.data(), p.size() * sizeof(double));
    mix(p.angular_velocity.data(), p.size() * sizeof(double));
    // a list that keeps no springs (a history-free law's) and one whose springs are all 0 hold
    // the same state, and hash alike
    const std::vector<double>& springs = c.state.neighbours.history;
    if (std::any_of(springs.begin(), springs.end(), [](double s) { return s != 0.0; }))
      mix(springs.data(), springs.size() * sizeof(double));
    fmt::print("time {:.9g} s\nstep {}\nparticles {}\nstate_hash {:016x}\n", c.state.time,
               c.state.steps, p.size(), h);
  });
}

void add_convert_command(CLI::App& app) {
  auto in = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "convert", "convert a thesis .in file to a scenario .toml, or a .toml with an explicit "
                 "particle list to .in (the direction follows the file endings)");
  cmd->add_option("input", *in, "FILE.in or FILE.toml")->required()->check(CLI::ExistingFile);
  cmd->add_option("output", *out, "FILE.toml or FILE.in")->required();
  cmd->callback([in, out] {
    const auto ext_in = fs::path(*in).extension(), ext_out = fs::path(*out).extension();
    if (ext_in == ".in" && ext_out == ".toml") {
      const ThesisFile f = read_thesis_in(read_file(*in), *in);
      const Scenario s = scenario_from_thesis(f, fs::path(*in).stem().string());
      write_file_atomically(*out, to_toml(s));
      fmt::print("wrote {} ({} particles)\n", *out, f.particles.size());
    } else if (ext_in == ".toml" && ext_out == ".in") {
      const ThesisFile f = thesis_from_scenario(load_scenario_file(*in));
      write_file_atomically(*out, write_thesis_in(f));
      fmt::print("wrote {} ({} particles)\n", *out, f.particles.size());
    } else {
      throw InvalidArgument("convert: give FILE.in FILE.toml or FILE.toml FILE.in (got '" +
                            ext_in.string() + "' to '" + ext_out.string() + "')");
    }
  });
}

} // namespace talus::cli
