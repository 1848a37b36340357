#pragma once
// A run driven from Python: the run of `talus run` (run/run.hpp, its folder made and locked as
// the command line makes it), stepped in pieces between which Python looks and changes things.
// Nothing here knows Python: module.cpp binds it.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cli/run/run_folder.hpp"
#include "run/run.hpp"
#include "scenario/scenario.hpp"

namespace talus::python {

class Session {
public:
  /// Builds (settles) `s` and starts its run in `dir` (which must not hold another run); threads
  /// >= 0 replaces simulation.threads. `stop_requested` is asked between stretches of steps (a
  /// Ctrl-C in Python): true checkpoints the run and ends the call of go.
  Session(const Scenario& s, const std::string& dir, int threads, bool quiet,
          std::function<bool()> stop_requested);
  /// Continues the run in `dir` from its last good checkpoint, as talus resume does.
  static std::unique_ptr<Session> resume(const std::string& dir, int threads, bool quiet,
                                         std::function<bool()> stop_requested);
  ~Session();

  /// Steps to step `until` (or the run's end, or a stop request): every output and event due on
  /// the way, as talus run makes them.
  run::RunOutcome go(std::uint64_t until);
  /// "key=value" changes from this step on, checked and recorded as a stage's are.
  void change(const std::vector<std::string>& set, const std::string& source);
  /// Grains added between steps (run::Run::add_grains): their ids.
  std::vector<std::uint32_t> add_grains(const std::vector<ParticleSpec>& grains,
                                        const std::string& source) {
    return run_->add_grains(grains, source);
  }
  /// Grains removed between steps by id (run::Run::remove_grains).
  void remove_grains(const std::vector<std::uint32_t>& ids, const std::string& source) {
    run_->remove_grains(ids, source);
  }
  /// Runs on to `duration` s in all (simulation.duration changed; an ended run goes on).
  void extend_to(double duration);
  /// A checkpoint now; stop_here: the checkpoint and run.json of a run stopped before its end.
  void checkpoint() { run_->checkpoint(); }
  void stop_here() { run_->stop_here(); }
  void flush() { run_->flush(); }

  const Simulation& simulation() const { return run_->simulation(); }
  const Scenario& scenario() const { return run_->scenario(); }
  const run::RunBook& book() const { return run_->book(); }
  const std::string& folder() const { return dir_; }
  bool ended() const { return run_->ended(); }

private:
  Session(cli::RunFolder folder, std::function<bool()> stop_requested, bool quiet);
  run::RunControl control(const Scenario& s);

  cli::RunFolder folder_; ///< locked while the session lives
  std::string dir_;
  bool quiet_ = true;
  std::function<bool()> stop_requested_;
  std::unique_ptr<run::Run> run_;
};

} // namespace talus::python
