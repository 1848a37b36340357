#pragma once
// Threads that never make a run much slower than one thread. On a machine another process keeps
// busy, a thread of a run shares its core, and every stage of every step waits at a barrier for
// it: two threads then run several times slower than one. The run times its stretches of steps
// now and then on all its threads and on one, and goes on with the faster; the results are the
// same bits whatever the count, so the choice changes only the speed.
#include <cstdint>

namespace talus {

class ThreadChooser {
public:
  /// `most`: the threads the system's size pays for; `every`: seconds of wall time between
  /// trials; `phase`: seconds each half of a trial runs at least (stretches of steps can be
  /// short, and one alone times noisily).
  explicit ThreadChooser(int most, double every = 20.0, double phase = 0.05)
      : most_(most), every_(every), phase_(phase) {}
  /// The threads for the next stretch of steps.
  int threads() const { return trying_ == 0 ? chosen_ : trying_; }
  /// The stretch just run took `seconds` for `steps` steps, at `now` s of wall time. Returns
  /// true when the choice changed.
  bool took(double seconds, std::uint64_t steps, double now);
  /// The last trial's times per step, s (0: none yet).
  double time_all() const { return per_step_all_; }
  double time_one() const { return per_step_one_; }

private:
  int most_;
  double every_, phase_;
  double seconds_ = 0.0; ///< of the trial's half under way
  std::uint64_t steps_ = 0;
  int chosen_ = most_;
  int trying_ = most_ > 1 ? most_ : 0; ///< a trial's thread count now (0: none under way)
  double next_trial_ = 0.0;
  double per_step_all_ = 0.0, per_step_one_ = 0.0;
};

} // namespace talus
