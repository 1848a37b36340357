// `talus bench linear`: the cost per particle-step against N for the same physics. Copies side
// by side of one settled packing (--tiles, as `bench dense2d --tiles`) from 1e3 to 1e6 disks,
// timed in turns in one process, round after round, so that a machine whose speed drifts from
// minute to minute (a shared host) slows every size
// alike; the figure of a size is the median of its rounds.
#include <algorithm>
#include <memory>
#include <vector>

#include <fmt/core.h>

#include "analysis/observables.hpp"
#include "cli/bench/bench_system.hpp"
#include "talus/error.hpp"

namespace talus::cli {

namespace {

struct LinearOptions {
  // settled for 1 s, not dense2d's 0.6 s: after 0.6 s the packing still compacts (2.85 contacts
  // per particle, 3.05 after 2000 steps more, 3.42 from 0.8 s on), and every size must be timed
  // in the same state although the small ones run a hundred times as many steps
  BenchSystem system{.settle_time = 1.0};
  std::size_t base = 32; // side of the settled square packing that is tiled
  std::vector<std::size_t> tiles{1, 10, 100, 1000};
  int rounds = 5;
  double particle_steps = 2e7; // per size and round: 20000 steps of 1e3 disks
  std::uint64_t min_steps = 200;
  std::string results = "bench/results";
};

void run_linear(const LinearOptions& o) {
  require(o.base >= 3, fmt::format("bench linear: --base {}; allowed: >= 3", o.base));
  require(o.rounds >= 1, fmt::format("bench linear: --rounds {}; allowed: >= 1", o.rounds));
  require(!o.tiles.empty(), "bench linear: --tiles is empty; allowed: one or more counts >= 1");
  std::vector<TimedRun> sizes;
  for (const std::size_t k : o.tiles) {
    require(k >= 1, "bench linear: --tiles holds 0; allowed: counts >= 1");
    BenchSystem s = o.system;
    s.tiles = k;
    s.n = o.base * o.base * k;
    TimedRun z;
    z.sim = std::make_unique<Simulation>(bench_simulation(s, "bench linear"));
    const double n = static_cast<double>(z.sim->world().particles.size());
    z.steps = std::max<std::uint64_t>(
        o.min_steps, static_cast<std::uint64_t>(std::llround(o.particle_steps / n)));
    z.sim->run(100); // warm up: caches, first rebuild
    sizes.push_back(std::move(z));
  }
  fmt::print("bench linear: copies of the settled {} x {} packing, {} thread(s), {} round(s)\n",
             o.base, o.base, sizes.front().sim->threads(), o.rounds);
  fmt::print("  (each round: ");
  for (std::size_t q = 0; q < sizes.size(); ++q)
    fmt::print("{}{}", q > 0 ? ", " : "", sizes[q].sim->world().particles.size());
  fmt::print(" disks)\n");
  time_in_turns(sizes, o.rounds);
  fmt::print(
      "| N | steps per round | ns per particle-step (median) | min | max | rebuilds per 1000 "
      "steps | contacts per particle |\n|---|---|---|---|---|---|---|\n");
  double lo = 0.0, hi = 0.0;
  std::string csv;
  for (std::size_t q = 0; q < sizes.size(); ++q) {
    const TimedRun& z = sizes[q];
    const double n = static_cast<double>(z.sim->world().particles.size());
    const double m = median(z.ns);
    lo = lo == 0.0 ? m : std::min(lo, m);
    hi = std::max(hi, m);
    const double contacts = 2.0 * static_cast<double>(contact_count(*z.sim)) / n;
    fmt::print("| {} | {} | {:.2f} | {:.2f} | {:.2f} | {:.1f} | {:.3f} |\n",
               z.sim->world().particles.size(), z.steps, m,
               *std::min_element(z.ns.begin(), z.ns.end()),
               *std::max_element(z.ns.begin(), z.ns.end()),
               1000.0 * static_cast<double>(z.builds) /
                   (static_cast<double>(z.steps) * static_cast<double>(o.rounds)),
               contacts);
    csv = append_result(
        o.results, {.benchmark = "dense2d_linear",
                    .n = z.sim->world().particles.size(),
                    .steps = z.steps,
                    .threads = z.sim->threads(),
                    .seconds_per_particle_step = 1e-9 * m,
                    .contacts_per_particle = contacts,
                    .nx = o.base * o.tiles[q],
                    .ny = o.base,
                    .engine_bytes_per_particle = static_cast<double>(z.sim->footprint_bytes()) / n,
                    .skin = z.sim->neighbours().skin});
  }
  fmt::print("largest / smallest median: {:.3f} (the cost is linear within {:.0f}%)\n", hi / lo,
             100.0 * (hi / lo - 1.0));
  fmt::print("appended to {} (benchmark dense2d_linear: the medians; bytes_per_particle 0, not "
             "measured with several systems in one process)\n",
             csv);
}

} // namespace

void add_bench_linear_command(CLI::App& bench) {
  auto o = std::make_shared<LinearOptions>();
  CLI::App* cmd = bench.add_subcommand(
      "linear", "the cost per particle-step from 1e3 to 1e6 disks for the same physics (copies "
                "of one settled packing, timed in turns, medians of rounds)");
  cmd->add_option("--base", o->base, "side of the settled square packing that is copied")
      ->capture_default_str()
      ->check(CLI::Range(3, 10000));
  cmd->add_option("--tiles", o->tiles, "copies side by side, one system per count")
      ->capture_default_str()
      ->delimiter(',')
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--rounds", o->rounds, "times every size is timed, in turns")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--particle-steps", o->particle_steps,
                  "particle-steps timed per size and round (steps = this / N)")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 1e12));
  cmd->add_option("--min-steps", o->min_steps, "fewest steps timed per size and round")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000000));
  cmd->add_option("--threads", o->system.threads, "threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  cmd->add_option("--settle-time", o->system.settle_time,
                  "settling time of the base packing, s (from 0.8 s on it no longer compacts)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 100.0));
  add_shared_bench_options(*cmd, o->system, o->results);
  cmd->callback([o] { run_linear(*o); });
}

} // namespace talus::cli
