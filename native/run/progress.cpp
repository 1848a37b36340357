#include "run/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unistd.h>

#include <fmt/core.h>

#include "simulation/simulation.hpp"

namespace talus::run {

void report_opening(const Simulation& sim, bool quiet) {
  if (quiet) return;
  // the engine uses fewer threads than asked where a thread would have too few particles to
  // repay its cost: say so rather than leave the user to wonder
  const int asked = sim.config().threads;
  if (asked > 0 && sim.max_threads() < asked)
    fmt::print("  {} of the {} threads asked: {} particles, and a thread needs about {} to pay "
               "for itself\n",
               sim.max_threads(), asked, sim.world().particles.size(),
               sim.config().min_particles_per_thread);
  else if (asked == 0)
    fmt::print("  threads: {} ({} particles; a thread needs about {} to pay for itself)\n",
               sim.max_threads(), sim.world().particles.size(),
               sim.config().min_particles_per_thread);
  if (sim.max_threads() > 1)
    fmt::print("  the run times its steps on {} threads and on 1 now and then, and goes on with "
               "the faster (a busy machine can make threads slower than one)\n",
               sim.max_threads());
  // the step specialised to the scene: what it leaves out (simulation/step_features.hpp)
  if (sim.step_description() == "general")
    fmt::print("  step: the general one (the scene uses every feature it has)\n");
  else
    fmt::print("  step specialised to the scene: {}\n", sim.step_description());
}

RunProgress::RunProgress(bool quiet, double duration, double thermo_interval, double timestep)
    : quiet_(quiet), tty_(!quiet && ::isatty(STDERR_FILENO)), duration_(duration),
      resolution_(std::max(thermo_interval, timestep)) {}

void RunProgress::report(double time, std::uint64_t step, std::uint64_t total, std::uint64_t stop,
                         double wall, std::uint64_t steps_done, double kinetic) {
  if (quiet_) return;
  const double fraction = static_cast<double>(step) / static_cast<double>(total);
  const double rate = wall > 0 ? static_cast<double>(steps_done) / wall : 0.0;
  const double eta = rate > 0 ? static_cast<double>(stop - step) / rate : 0.0;
  if (tty_) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_print_ < std::chrono::milliseconds(250)) return;
    last_print_ = now;
    const int filled = static_cast<int>(fraction * 30.0);
    fmt::print(stderr, "\r  t = {:.4f} / {:.4f} s [{}{}] {:5.1f}%  {:.3g} steps/s  ETA {:.0f} s   ",
               time, duration_, std::string(static_cast<std::size_t>(filled), '#'),
               std::string(static_cast<std::size_t>(30 - filled), '.'), 100.0 * fraction, rate,
               eta);
    printed_ = true;
  } else if (fraction >= next_report_) {
    next_report_ = std::floor(fraction * 10.0 + 1.0) / 10.0;
    fmt::print("t = {} / {} s ({:.0f}%), {:.3g} steps/s, E_kin = {:.4e} J, ETA {:.0f} s\n",
               time_text(time), time_text(duration_), 100.0 * fraction, rate, kinetic, eta);
    std::fflush(stdout);
  }
}

void RunProgress::finish() {
  if (printed_) fmt::print(stderr, "\n");
}

std::string RunProgress::time_text(double t) const {
  const int decimals =
      std::clamp(static_cast<int>(std::ceil(-std::log10(resolution_) - 1e-9)), 0, 9);
  return fmt::format("{:.{}f}", t, decimals);
}

} // namespace talus::run
