#pragma once
// What a run tells its user while it goes: a progress bar redrawn in place on a terminal, or a
// line at every tenth of the run when the output goes to a file or a pipe.
#include <chrono>
#include <cstdint>
#include <string>

namespace talus {
class Simulation;
}

namespace talus::run {

/// The run's opening lines (unless `quiet`): the step specialised to the scene (what it leaves
/// out), and the threads taken when fewer than asked.
void report_opening(const Simulation& sim, bool quiet);

class RunProgress {
public:
  /// `quiet`: nothing at all. `duration` (s) is the whole run's; `thermo_interval` and
  /// `timestep` (s) set how many decimals a time is shown with.
  RunProgress(bool quiet, double duration, double thermo_interval, double timestep);
  /// At simulated time `time`, step `step` of `total` (the run stops at `stop`), after `wall`
  /// seconds and `steps_done` steps of this session; `kinetic` (J) for the line's E_kin.
  void report(double time, std::uint64_t step, std::uint64_t total, std::uint64_t stop, double wall,
              std::uint64_t steps_done, double kinetic);
  /// The run's whole length changed (talus resume --duration), s.
  void set_duration(double duration) { duration_ = duration; }
  /// Ends a progress bar's line, if one was drawn.
  void finish();
  /// A time as the thermo interval resolves it: 0.61 s, not the 0.60999 s of a step's rounding.
  std::string time_text(double t) const;
  /// Whether the progress goes to a terminal (a bar redrawn in place).
  bool on_terminal() const { return tty_; }

private:
  bool quiet_, tty_;
  double duration_, resolution_;
  bool printed_ = false;
  double next_report_ = 0.1;
  std::chrono::steady_clock::time_point last_print_{};
};

} // namespace talus::run
