// `talus bench dense2d`: the reference benchmark, timed side by side with LAMMPS.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <vector>

#include <fmt/core.h>

#include "analysis/observables.hpp"
#include "cli/bench_system.hpp"
#include "cli/commands.hpp"
#include "io/checkpoint.hpp"
#include "scenario/dense2d.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

struct BenchOptions {
  BenchSystem system;
  std::uint64_t steps = 2000;
  int rounds = 1;
  bool lammps = false;
  std::string results = "bench/results";
  std::string lammps_inputs;
};

// Runs LAMMPS on the same system; returns its seconds per particle-step (0 if it failed).
double run_lammps(const BenchOptions& o, std::size_t nx, std::size_t ny) {
  if (std::system("command -v lmp > /dev/null 2>&1") != 0) {
    fmt::print("lammps: `lmp` is not on the PATH (apt-get install lammps); skipped\n");
    return 0.0;
  }
  const fs::path dir = fs::absolute(fs::path(o.system.cache) / "lammps");
  fs::create_directories(dir);
  for (const char* f : {"lammps-settle.in", "lammps-bench.in"})
    fs::copy_file(fs::path(o.lammps_inputs) / f, dir / f, fs::copy_options::overwrite_existing);
  const std::string vars = fmt::format("-var nx {} -var ny {}", nx, ny);
  if (!fs::exists(dir / fmt::format("settled_{}x{}.restart", nx, ny))) {
    fmt::print("lammps: settling its own packing (lammps-settle.in)...\n");
    std::fflush(stdout);
    if (std::system(
            fmt::format("cd '{}' && lmp -in lammps-settle.in {} -log settle.log > settle.out 2>&1",
                        dir.string(), vars)
                .c_str()) != 0) {
      fmt::print("lammps: settling failed; see {}/settle.out\n", dir.string());
      return 0.0;
    }
  }
  if (std::system(fmt::format("cd '{}' && lmp -in lammps-bench.in {} -var nsteps {} -log bench.log "
                              "> bench.out 2>&1",
                              dir.string(), vars, o.steps)
                      .c_str()) != 0) {
    fmt::print("lammps: the run failed; see {}/bench.out\n", dir.string());
    return 0.0;
  }
  // "Loop time of 12.3 on 1 procs for 2000 steps with 10000 atoms"
  const std::string log = read_file((dir / "bench.log").string());
  const auto at = log.find("Loop time of ");
  double seconds = 0.0, steps = 0.0, atoms = 0.0;
  int procs = 0;
  if (at == std::string::npos ||
      std::sscanf(log.c_str() + at, "Loop time of %lf on %d procs for %lf steps with %lf atoms",
                  &seconds, &procs, &steps, &atoms) != 4 ||
      steps <= 0 || atoms <= 0) {
    fmt::print("lammps: no 'Loop time' in {}/bench.log\n", dir.string());
    return 0.0;
  }
  return seconds / (steps * atoms);
}

void run_bench(const BenchOptions& o) {
  require(o.rounds >= 1, fmt::format("bench dense2d: --rounds {}; allowed: >= 1", o.rounds));
  const std::size_t ny = bench_base_side(o.system, "bench dense2d"), nx = ny * o.system.tiles;
  Simulation sim = bench_simulation(o.system, "bench dense2d");
  const double n = static_cast<double>(sim.world().particles.size());
  sim.run(100); // warm up: caches, first rebuild
  // every round times the same steps from this state (as LAMMPS' runs start from its restart)
  const SimulationState warm = o.rounds > 1 ? sim.state() : SimulationState{};
  const std::uint64_t builds_before = sim.neighbours().builds;
  const std::uint64_t choices_before = sim.candidate_choices();
  const std::uint64_t tests_before = sim.drift_tests();
  std::vector<double> talus_rounds{time_steps(sim, o.steps)};
  const std::uint64_t builds = sim.neighbours().builds - builds_before;
  const std::uint64_t choices = sim.candidate_choices() - choices_before;
  const std::uint64_t tests = sim.drift_tests() - tests_before;
  const double contacts = 2.0 * static_cast<double>(contact_count(sim)) / n;
  // with rounds, a copy of the state is held too: the peak is not the engine's alone
  const double bytes = o.rounds > 1 ? 0.0 : peak_rss_bytes() / n;
  const double engine_bytes = static_cast<double>(sim.footprint_bytes()) / n;
  const bool with_lammps = o.lammps && o.system.tiles == 1;
  if (o.lammps && o.system.tiles > 1)
    fmt::print("lammps: not run with --tiles (LAMMPS would settle the wide system itself)\n");
  // talus and LAMMPS in turns, round after round: a slow minute of the host falls on both
  std::vector<double> lammps_rounds;
  for (int r = 0; r < o.rounds; ++r) {
    if (r > 0) {
      Simulation again = Simulation::restore(warm, sim.config());
      talus_rounds.push_back(time_steps(again, o.steps));
    }
    if (with_lammps) {
      const double l = run_lammps(o, nx, ny);
      if (l <= 0.0) break; // it said why
      lammps_rounds.push_back(l);
    }
    if (o.rounds > 1) {
      fmt::print("  round {}: talus {:.2f} ns per particle-step", r + 1, 1e9 * talus_rounds.back());
      if (lammps_rounds.size() == static_cast<std::size_t>(r + 1))
        fmt::print(", LAMMPS {:.2f}, LAMMPS / talus {:.2f}", 1e9 * lammps_rounds.back(),
                   lammps_rounds.back() / talus_rounds.back());
      fmt::print("\n");
      std::fflush(stdout);
    }
  }
  const double per = median(talus_rounds);
  const double lammps = lammps_rounds.empty() ? 0.0 : median(lammps_rounds);

  fmt::print("dense2d: {} disks ({} x {}), {} steps, {} thread(s)\n", sim.world().particles.size(),
             nx, ny, o.steps, sim.threads());
  fmt::print("  ns per particle-step:       {:.2f}{}\n", per * 1e9,
             o.rounds > 1 ? fmt::format(" (median of {} rounds)", talus_rounds.size()) : "");
  fmt::print("  particle-steps per second:  {:.4g}\n", 1.0 / per);
  fmt::print("  contacts per particle:      {:.3f}\n", contacts);
  fmt::print("  list entries per particle:  {:.3f} (half list; {:.1f}% cross a force block)\n",
             static_cast<double>(sim.neighbours().pair_count()) / n,
             100.0 * sim.neighbours().block_first_slot.back() /
                 std::max<double>(1.0, static_cast<double>(sim.neighbours().pair_count())));
  fmt::print("  engine memory per particle: {:.0f} bytes (state, lists, history, buffers)\n",
             engine_bytes);
  if (bytes > 0.0)
    fmt::print("  peak memory per particle:   {:.0f} bytes (the process' peak resident size)\n",
               bytes);
  else
    fmt::print("  peak memory per particle:   not measured with --rounds (a copy of the state is "
               "held for the rounds)\n");
  fmt::print("  neighbour-list rebuilds:    {} in {} steps\n", builds, o.steps);
  fmt::print("  contact candidates chosen:  {} times; drift tested against the build {} times\n",
             choices, tests);
  fmt::print("  skin:                       {:.3g} mm ({})\n", 1e3 * sim.neighbours().skin,
             o.system.skin > 0.0 ? "--skin" : "automatic; --skin 0.001 is the LAMMPS input's");
  if (lammps > 0.0) {
    const bool all = lammps_rounds.size() == talus_rounds.size();
    fmt::print("  LAMMPS ns per particle-step: {:.2f}{}\n", lammps * 1e9,
               o.rounds > 1 ? fmt::format(" (median of {} rounds)", lammps_rounds.size()) : "");
    fmt::print("  LAMMPS time / talus time:    {:.2f}{}\n", lammps / per,
               o.rounds > 1 && all ? " (of the medians)" : "");
  }
  const std::string csv = append_result(o.results, {.n = sim.world().particles.size(),
                                                    .steps = o.steps,
                                                    .threads = sim.threads(),
                                                    .seconds_per_particle_step = per,
                                                    .contacts_per_particle = contacts,
                                                    .peak_bytes_per_particle = bytes,
                                                    .lammps_seconds_per_particle_step = lammps,
                                                    .nx = nx,
                                                    .ny = ny,
                                                    .engine_bytes_per_particle = engine_bytes,
                                                    .skin = sim.neighbours().skin});
  fmt::print("appended to {}\n", csv);
}

// The thesis' table 2.2: 1000 steps at dt = 1e-6 s for 382 to 3885 disks, Verlet-list column.
void run_thesis_table(int threads) {
  struct Row {
    std::size_t n;
    double thesis_minutes;
  };
  static constexpr Row rows[] = {
      {382, 0.0166667}, {685, 0.0833333}, {1285, 0.183333}, {2485, 0.4}, {3885, 0.733333}};
  fmt::print("| disks | thesis, Verlet list (min) | talus (s) | talus (min) | speed-up |\n"
             "|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    const auto nx = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(r.n))));
    Dense2d d = build_dense2d(nx, (r.n + nx - 1) / nx, 12345, r.n);
    d.config.threads = threads;
    Simulation settle(std::move(d.world), d.config);
    settle.run(30'000); // 0.3 s: a settled packing, as the thesis' runs started from
    SimulationConfig fine = d.config;
    fine.timestep = 1.0e-6; // the thesis' timestep
    Simulation sim = Simulation::restore(settle.state(), fine);
    const auto start = std::chrono::steady_clock::now();
    sim.run(1000);
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fmt::print("| {} | {:.3f} | {:.4f} | {:.5f} | {:.0f}x |\n", r.n, r.thesis_minutes, s, s / 60.0,
               r.thesis_minutes * 60.0 / s);
  }
}

} // namespace

void add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  o->lammps_inputs = std::string(TALUS_SOURCE_DIR) + "/inputs/dense2d";
  CLI::App* bench = app.add_subcommand("bench", "benchmarks (figures, not tests)");
  bench->require_subcommand(1);
  CLI::App* cmd = bench->add_subcommand(
      "dense2d",
      "a settled polydisperse packing on a floor, periodic in x (inputs/dense2d/README.md)");
  cmd->add_option("--n", o->system.n, "number of disks (rounded to a square)")
      ->capture_default_str()
      ->check(CLI::Range(9, 100000000));
  cmd->add_option("--tiles", o->system.tiles,
                  "copies side by side of the settled square packing of n / tiles disks (a "
                  "large system without settling it)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--sort-every", o->system.sort_every,
                  "steps between renumberings of the particles in the order of their cells (0: "
                  "never; the settled packing is cached in the order it settled into)")
      ->capture_default_str();
  cmd->add_option("--steps", o->steps, "timed steps")->capture_default_str();
  cmd->add_option("--rounds", o->rounds,
                  "times the steps are timed from the same state, in turns with LAMMPS if "
                  "--lammps: the figures are the medians (on a shared host a slow minute then "
                  "falls on both)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--threads", o->system.threads, "threads (0: all cores)")->capture_default_str();
  cmd->add_flag("--lammps", o->lammps,
                "also run LAMMPS (lmp) on the same system and print the ratio");
  add_shared_bench_options(*cmd, o->system, o->results,
                           "neighbour-list skin, m (0: automatic, as in a run; 0.001 is the "
                           "LAMMPS input's; the physics is the same)");
  cmd->add_option("--lammps-inputs", o->lammps_inputs,
                  "folder with lammps-settle.in and lammps-bench.in")
      ->capture_default_str();
  cmd->add_option("--settle-time", o->system.settle_time, "settling time, s")
      ->capture_default_str();
  cmd->callback([o] { run_bench(*o); });

  add_bench_linear_command(*bench);
  add_bench_threads_command(*bench);

  auto threads = std::make_shared<int>(1);
  CLI::App* thesis = bench->add_subcommand(
      "thesis",
      "the thesis' table 2.2 (1000 steps of 382 to 3885 disks at dt = 1e-6 s) beside talus");
  thesis->add_option("--threads", *threads, "threads (0: all cores)")->capture_default_str();
  thesis->callback([threads] { run_thesis_table(*threads); });
}

} // namespace talus::cli
