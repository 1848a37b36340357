// A new run: the scenario settled (built) in its locked run folder, what was built said, and the
// run started (talus run, and talus resume of a run stopped before its first checkpoint).
#include <cstdio>

#include <fmt/core.h>

#include "cli/run/run_loop.hpp"
#include "scenario/file/toml_reader.hpp"
#include "scenario/soft_contacts.hpp"
#include "scenario/timestep_accuracy.hpp"

namespace talus::cli {

int settle_and_start(const Scenario& s, RunFolder folder, const RunOptions& o,
                     const std::string& source) {
  struct Interrupted {
    double time;
  };
  catch_stop_signals();
  BuiltScenario built;
  try {
    Scenario settle = s; // --threads applies to the settling too
    if (o.threads >= 0) settle.simulation.threads = o.threads;
    built = build_scenario(settle, [&](double t, double ke) {
      if (stop_signal()) throw Interrupted{t};
      if (o.quiet) return;
      fmt::print("  settling: t = {:.4f} s, E_kin = {:.4e} J\n", t, ke);
      std::fflush(stdout);
    });
  } catch (const Interrupted& i) { // the folder stays: resume starts the run again
    fmt::print(stderr,
               "talus: interrupted while settling, at t = {:.4g} s of it, before the run's first "
               "checkpoint; start it again with: talus resume {}\n",
               i.time, folder.path().string());
    return exit_interrupted;
  } catch (const ScenarioError& e) { // say which file the key is in; leave nothing behind
    folder.discard();
    throw ScenarioError(source + ": " + e.what());
  } catch (...) {
    folder.discard();
    throw;
  }
  if (!o.quiet) {
    std::size_t free = built.world.particles.count(Kind::free);
    fmt::print("  {} grains, {} wall particles, {} wall segments; dt = {:.4g} s (collision time "
               "{:.4g} s){}\n",
               free, built.world.particles.size() - free, built.world.walls.size(),
               built.config.timestep, built.collision_time,
               built.settle_time > 0 ? fmt::format("; settled in {:.3f} s", built.settle_time)
                                     : "");
    if (const RestitutionError e = expected_restitution_error(built); !e.basis.empty())
      fmt::print("  dt = collision time / {:.4g}: restitution error about {:.1e} ({}; "
                 "docs/accuracy.md)\n",
                 built.collision_time / built.config.timestep, e.error, e.basis);
    if (!built.settled) fmt::print("  warning: not settled within packing.settle_max_time\n");
    std::fflush(stdout);
  }
  if (const std::string w = soft_contact_warning(s, built); !w.empty())
    fmt::print(stderr, "talus: warning: {}\n", w);
  return start_run(s, std::move(built), std::move(folder), o);
}

} // namespace talus::cli
