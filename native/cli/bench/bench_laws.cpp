// `talus bench laws`: what a scene pays for its tangential law. The dense2d system settled with
// each tangential law (frictionless, the thesis' capped viscous friction, Cundall-Strack), every
// one timed in turns, round after round (time_in_turns), so that a drift of the
// machine's speed slows them alike. Each copy runs the step specialised to its scene
// (simulation/step_features.hpp); the figures are ns per particle-step and the engine's bytes per
// particle, against the Cundall-Strack copy.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "analysis/observables.hpp"
#include "cli/bench/bench_system.hpp"
#include "talus/error.hpp"

namespace talus::cli {

namespace {

struct LawsOptions {
  BenchSystem system;
  std::vector<std::string> laws{"none", "coulomb", "cundall_strack"};
  std::uint64_t steps = 50; // per copy and round
  int rounds = 51;
  bool general = false; ///< also a copy per law in the general step
  std::string results = "bench/results";
};

// The targets of the specialised steps against Cundall-Strack (issue "model only what a scene
// needs"): speed-up and share of its bytes per particle; 0 for none.
struct Target {
  std::string_view law;
  double speed_up, bytes_share;
};
constexpr Target targets[] = {{"none", 1.4, 0.0}, {"coulomb", 1.15, 0.8}};

std::string target_text(const std::string& law, double speed_up, double bytes_share) {
  for (const Target& t : targets) {
    if (t.law != law) continue;
    std::string s = fmt::format("speed-up >= {:.2f}: {}", t.speed_up,
                                speed_up >= t.speed_up ? "met" : "NOT met");
    if (t.bytes_share > 0.0)
      s += fmt::format("; bytes <= {:.2f}: {}", t.bytes_share,
                       bytes_share <= t.bytes_share ? "met" : "NOT met");
    return s;
  }
  return law == "cundall_strack" ? "reference" : "-";
}

// The copies to time: one per law (and its general step with --general), each started again
// from the same packing for every round.
struct LawRuns {
  SimulationState settled;
  std::vector<TimedRun> runs;
  std::vector<std::string> labels;  ///< "coulomb", "coulomb (general step)"
  std::vector<std::string> benches; ///< the results CSV's names: dense2d_coulomb(_general)
  std::vector<SimulationConfig> configs;

  bool general(std::size_t k) const { return labels[k].ends_with("(general step)"); }
  void start(std::size_t k) {
    runs[k].sim = std::make_unique<Simulation>(Simulation::restore(settled, configs[k]));
    runs[k].sim->use_general_step(general(k));
    if (configs[k].tangential_law != law_id<Frictionless>) return;
    // frictionless grains do not turn: the spin friction gave them while settling is taken away,
    // as a frictionless scene would have none
    Particles& p = runs[k].sim->edit_world().particles;
    std::fill(p.angular_velocity.begin(), p.angular_velocity.end(), 0.0);
    std::fill(p.torque.begin(), p.torque.end(), 0.0);
    std::fill(p.torque_previous.begin(), p.torque_previous.end(), 0.0);
  }
};

// Every copy starts each round from the same packing, settled with Cundall-Strack, with its own
// law: taking friction away lets a packing that friction held up come apart, so a copy that ran
// on would be timed on fewer and fewer contacts. Short rounds from the same state time every law
// on nearly the contacts of the same packing.
LawRuns law_runs(const LawsOptions& o, const Simulation& base) {
  LawRuns l{base.state(), {}, {}, {}, {}};
  for (const std::string& name : o.laws) {
    const auto law = find_law<TangentialLaw>(name);
    require(law.has_value(), fmt::format("bench laws: --laws holds '{}'; allowed: {}", name,
                                         law_names<TangentialLaw>()));
    SimulationConfig config = base.config();
    config.tangential_law = *law;
    for (const bool general : {false, true}) {
      if (general && !o.general) continue;
      TimedRun z;
      z.steps = o.steps;
      l.runs.push_back(std::move(z));
      l.labels.push_back(general ? name + " (general step)" : name);
      l.benches.push_back("dense2d_" + name + (general ? "_general" : ""));
      l.configs.push_back(config);
    }
  }
  return l;
}

// The rounds, every other one in the opposite order.
void time_rounds(LawRuns& l, int rounds, std::uint64_t steps) {
  for (std::size_t k = 0; k < l.runs.size(); ++k) { // warm up: caches, code
    l.start(k);
    l.runs[k].sim->run(steps);
  }
  for (int r = 0; r < rounds; ++r) {
    for (std::size_t q = 0; q < l.runs.size(); ++q) {
      const std::size_t k = r % 2 == 0 ? q : l.runs.size() - 1 - q;
      l.start(k);
      l.runs[k].ns.push_back(1e9 * time_steps(*l.runs[k].sim, steps));
    }
    fmt::print("  round {}:", r + 1);
    for (const TimedRun& z : l.runs) fmt::print(" {:.2f}", z.ns.back());
    fmt::print(" ns per particle-step\n");
    std::fflush(stdout);
  }
}

// Each copy's bytes per particle by what they hold (Simulation::footprint).
void print_footprints(const LawRuns& l) {
  const double n = static_cast<double>(l.settled.world.particles.size());
  fmt::print("| tangential law | step | particles | integrator | neighbour list | history | "
             "contact candidates | other | total (bytes per particle) |\n"
             "|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t k = 0; k < l.runs.size(); ++k) {
    const Footprint f = l.runs[k].sim->footprint();
    const auto per = [&](std::size_t b) { return static_cast<double>(b) / n; };
    fmt::print("| {} | {} | {:.1f} | {:.1f} | {:.1f} | {:.1f} | {:.1f} | {:.1f} | {:.1f} |\n",
               l.labels[k], l.runs[k].sim->step_description(), per(f.particles), per(f.integrator),
               per(f.list), per(f.history), per(f.candidates), per(f.other), per(f.total()));
  }
}

// The table, against the Cundall-Strack copy if there is one, and the results CSV's rows.
void report(const LawsOptions& o, const LawRuns& l, std::size_t nx, std::size_t ny) {
  const auto reference = std::find(l.labels.begin(), l.labels.end(), "cundall_strack");
  const TimedRun* cs =
      reference == l.labels.end() ? nullptr : &l.runs[reference - l.labels.begin()];
  const double n = static_cast<double>(l.settled.world.particles.size());
  fmt::print("| tangential law | step | ns per particle-step (median) | min | max | bytes per "
             "particle | contacts per particle | against cundall_strack: speed, bytes | target "
             "|\n|---|---|---|---|---|---|---|---|---|\n");
  std::string csv;
  for (std::size_t k = 0; k < l.runs.size(); ++k) {
    const TimedRun& z = l.runs[k];
    const double m = median(z.ns);
    const double bytes = static_cast<double>(z.sim->footprint_bytes()) / n;
    const double contacts = 2.0 * static_cast<double>(contact_count(*z.sim)) / n;
    std::string against = "-", target = "-";
    if (cs != nullptr) {
      // the median of the rounds' own ratios: a round's copies ran within seconds of each other
      std::vector<double> speed_up;
      for (std::size_t r = 0; r < z.ns.size(); ++r) speed_up.push_back(cs->ns[r] / z.ns[r]);
      const double share = bytes / (static_cast<double>(cs->sim->footprint_bytes()) / n);
      against = fmt::format("{:.2f}x, {:.2f}", median(speed_up), share);
      target = target_text(l.labels[k], median(speed_up), share);
    }
    fmt::print("| {} | {} | {:.2f} | {:.2f} | {:.2f} | {:.0f} | {:.3f} | {} | {} |\n", l.labels[k],
               z.sim->step_description(), m, *std::min_element(z.ns.begin(), z.ns.end()),
               *std::max_element(z.ns.begin(), z.ns.end()), bytes, contacts, against, target);
    csv = append_result(o.results, {.benchmark = l.benches[k],
                                    .n = l.settled.world.particles.size(),
                                    .steps = z.steps,
                                    .threads = z.sim->threads(),
                                    .seconds_per_particle_step = 1e-9 * m,
                                    .contacts_per_particle = contacts,
                                    .nx = nx,
                                    .ny = ny,
                                    .engine_bytes_per_particle = bytes,
                                    .skin = z.sim->neighbours().skin});
  }
  fmt::print("appended to {} (benchmarks dense2d_<law>: the medians; peak bytes 0, not measured "
             "with several systems in one process)\n",
             csv);
}

void run_laws(const LawsOptions& o) {
  require(o.rounds >= 1, fmt::format("bench laws: --rounds {}; allowed: >= 1", o.rounds));
  require(!o.laws.empty(), "bench laws: --laws is empty; allowed: " + law_names<TangentialLaw>());
  const std::size_t ny = bench_base_side(o.system, "bench laws"), nx = ny * o.system.tiles;
  Simulation base = bench_simulation(o.system, "bench laws");
  base.run(1); // the list built: a round's steps do not start with a build
  LawRuns l = law_runs(o, base);
  fmt::print("bench laws: {} disks ({} x {}), {} steps per round, {} round(s), {} thread(s)\n",
             base.world().particles.size(), nx, ny, o.steps, o.rounds, base.threads());
  fmt::print("  (each round: {})\n", fmt::format("{}", fmt::join(l.labels, ", ")));
  time_rounds(l, o.rounds, o.steps);
  report(o, l, nx, ny);
  print_footprints(l);
}

} // namespace

void add_bench_laws_command(CLI::App& bench) {
  auto o = std::make_shared<LawsOptions>();
  CLI::App* cmd = bench.add_subcommand(
      "laws", "the dense2d system with each tangential law, each in the step specialised to it "
              "(a copy per law, timed in turns, medians of rounds, bytes per particle)");
  cmd->add_option("--n", o->system.n, "number of disks (rounded to a square)")
      ->capture_default_str()
      ->check(CLI::Range(9, 100000000));
  cmd->add_option("--laws", o->laws, "tangential laws, one copy each")
      ->capture_default_str()
      ->delimiter(',');
  cmd->add_option("--steps", o->steps,
                  "steps per copy and round, each round from the settled packing")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000000));
  cmd->add_flag("--general", o->general,
                "also a copy per law in the general step, which does everything whatever the "
                "scene uses");
  cmd->add_option("--rounds", o->rounds, "times every copy is timed, in turns")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--threads", o->system.threads, "threads (0: all cores)")->capture_default_str();
  add_shared_bench_options(*cmd, o->system, o->results);
  cmd->callback([o] { run_laws(*o); });
}

} // namespace talus::cli
