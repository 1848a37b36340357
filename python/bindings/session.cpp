#include "session.hpp"

#include <filesystem>

#include <fmt/core.h>

#include "cli/run/run_loop.hpp"
#include "run/progress.hpp"
#include "scenario/build.hpp"
#include "scenario/file/load.hpp"
#include "scenario/file/stages.hpp"

namespace fs = std::filesystem;

namespace talus::python {

Session::Session(cli::RunFolder folder, std::function<bool()> stop_requested, bool quiet)
    : folder_(std::move(folder)), dir_(folder_.path().string()), quiet_(quiet),
      stop_requested_(std::move(stop_requested)) {}

Session::Session(const Scenario& s, const std::string& dir, int threads, bool quiet,
                 std::function<bool()> stop_requested)
    : Session(cli::RunFolder::create(dir, s), std::move(stop_requested), quiet) {
  BuiltScenario built;
  try {
    Scenario settle = s; // the threads asked for settle the grains too
    if (threads >= 0) settle.simulation.threads = threads;
    built = build_scenario(settle);
  } catch (...) { // nothing left behind
    folder_.discard();
    throw;
  }
  auto [sim, book] = cli::begin_run(s, std::move(built), folder_, threads);
  run::report_opening(sim, quiet_);
  run_ = std::make_unique<run::Run>(s, std::move(sim), std::move(book), folder_.path(), control(s),
                                    true);
}

std::unique_ptr<Session> Session::resume(const std::string& dir, int threads, bool quiet,
                                         std::function<bool()> stop_requested) {
  const fs::path d(dir);
  if (!fs::exists(d / "scenario.toml"))
    throw InvalidArgument("'" + dir + "' is not a talus run folder (no scenario.toml)");
  cli::RunFolder folder = cli::RunFolder::open(dir);
  if (cli::never_checkpointed(d))
    throw InvalidArgument("'" + dir + "' was stopped before its first checkpoint; start it again " +
                          "with talus.Simulation('" + (d / "scenario.toml").string() +
                          "', out=...)");
  cli::RunOptions o;
  o.threads = threads;
  o.quiet = quiet;
  std::unique_ptr<Session> s(new Session(std::move(folder), std::move(stop_requested), quiet));
  cli::Resumption r = cli::prepare_resume(s->folder_, o);
  run::report_opening(r.sim, quiet);
  run::RunControl c = s->control(r.scenario);
  c.set_now = std::move(r.set);
  c.set_now_source = std::move(r.source);
  s->run_ = std::make_unique<run::Run>(r.scenario, std::move(r.sim), std::move(r.book),
                                       s->folder_.path(), std::move(c), false);
  return s;
}

Session::~Session() = default;

run::RunControl Session::control(const Scenario& s) {
  run::RunControl c;
  c.quiet = quiet_;
  c.folder_gone = [this] { return folder_.gone(); };
  const std::string file = (folder_.path() / "scenario.toml").string();
  c.scenario_with = [file](const std::vector<std::string>& changes) {
    return load_scenario_file(file, changes);
  };
  c.stop_requested = stop_requested_;
  c.end_pictures = [this, s](const run::RunBook& b) {
    cli::scenario_pictures(s, folder_.path(), b, quiet_);
  };
  return c;
}

run::RunOutcome Session::go(std::uint64_t until) {
  if (ended()) return run::RunOutcome::completed;
  return run_->go(until);
}

void Session::change(const std::vector<std::string>& set, const std::string& source) {
  for (const std::string& x : set) {
    const std::size_t eq = x.find('=');
    const std::string key = eq == std::string::npos ? x : x.substr(0, eq);
    if (!changeable_during_run(key))
      throw ScenarioError("'" + key +
                          "' cannot change during a run; allowed: " + changeable_keys_text());
  }
  run_->change(set, source);
}

void Session::extend_to(double duration) {
  if (!(duration > simulation().time()))
    throw InvalidArgument(fmt::format("a duration of {:g} s: the run is at t = {:.9g} s already; "
                                      "allowed: a longer whole length",
                                      duration, simulation().time()));
  run_->change({fmt::format("simulation.duration={}", duration)}, "python");
  run_->go_on();
}

} // namespace talus::python
