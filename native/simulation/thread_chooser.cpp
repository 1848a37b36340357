#include "simulation/thread_chooser.hpp"

namespace talus {

bool ThreadChooser::took(double seconds, std::uint64_t steps, double now) {
  if (most_ <= 1 || steps == 0) return false;
  if (trying_ != 0) {
    seconds_ += seconds, steps_ += steps;
    if (seconds_ < phase_) return false;
  }
  const double per_step = trying_ != 0 ? seconds_ / static_cast<double>(steps_) : 0.0;
  seconds_ = 0.0, steps_ = 0;
  if (trying_ == most_) { // the trial's first half: all threads; then one
    per_step_all_ = per_step;
    trying_ = 1;
    return false;
  }
  if (trying_ == 1) {
    per_step_one_ = per_step;
    trying_ = 0;
    next_trial_ = now + every_;
    const int before = chosen_;
    chosen_ = per_step_one_ < per_step_all_ ? 1 : most_;
    return chosen_ != before;
  }
  if (now >= next_trial_) trying_ = most_;
  return false;
}

} // namespace talus
