// `talus bench dense2d`: the reference benchmark, timed side by side with LAMMPS.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "analysis/observables.hpp"
#include "cli/bench/bench_system.hpp"
#include "cli/commands.hpp"
#include "io/checkpoint.hpp"
#include "scenario/dense2d.hpp"
#include "talus/error.hpp"
#include "talus/material_keys.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

struct BenchOptions {
  BenchSystem system;
  std::uint64_t steps = 2000;
  int rounds = 1;
  bool lammps = false;
  std::string laws = "hooke";            ///< "hooke" (LAMMPS' gran/hooke/history) or "thesis"
  std::string lammps_packing = "native"; ///< LAMMPS times the "native" packing, or its "own"
  std::string results = "bench/results";
  std::string lammps_inputs;
};

// How LAMMPS runs the timed steps: which program, which pair style, on how many ranks.
struct LammpsRun {
  std::string label;   ///< for the log file's name and the messages
  std::string program; ///< lmp, or the package's talus-lmp
  std::string pair;    ///< lammps-bench.in's pair_style arguments; empty: the deck's own
  std::string coeff;   ///< and its pair_coeff coefficients
  int ranks = 1;       ///< MPI ranks (mpirun beyond 1)
};

// The path of the package's launcher where the build made it, else "".
std::string talus_lmp() {
#ifdef TALUS_LMP
  return fs::exists(TALUS_LMP) ? std::string(TALUS_LMP) : std::string();
#else
  return {};
#endif
}

// The LAMMPS runs beside the native engine: with --laws hooke LAMMPS' own gran/hooke/history
// (the deck's); with --laws thesis pair_style granthesis in talus-lmp, and for comparison
// granthesis with the linear law and LAMMPS' own gran/hooke, which computes that same law (no
// history, the viscous friction capped): the one measures the package against LAMMPS' own code
// on the same work, where the Hertz law costs a square root and more per contact.
std::vector<LammpsRun> lammps_runs(const BenchOptions& o, int ranks) {
  if (o.laws == "hooke") return {{"gran/hooke/history", "lmp", "", "", ranks}};
  const std::string launcher = talus_lmp();
  if (launcher.empty()) {
    fmt::print("lammps: talus-lmp was not built (LAMMPS' headers, liblammps-dev, were not "
               "found): pair_style granthesis skipped\n");
    return {};
  }
  // gran/hooke in talus-lmp too: the same library as lmp, and it reads the restart file that
  // granthesis' settling wrote (lmp does not know the style named in it)
  return {{"granthesis", launcher, "granthesis hertz coulomb",
           pair_coefficient_words(dense2d_thesis_material()), ranks},
          {"granthesis-linear", launcher, "granthesis linear coulomb",
           pair_coefficient_words(dense2d_material()), ranks},
          {"gran/hooke", launcher, "gran/hooke 1.0e5 NULL 1.0e2 NULL 0.5 1", "", ranks}};
}

// The state the native engine times, as a LAMMPS data file (atom_style sphere, 2d): LAMMPS then
// times the very same packing. The density gives each disk the native mass, as LAMMPS computes a
// sphere's (the dense2d disks have it: inputs/dense2d/README.md), to rounding.
std::string lammps_data(const Simulation& sim) {
  const Particles& p = sim.world().particles;
  const Domain& d = sim.world().domain;
  std::string out = fmt::format("LAMMPS data file: the native dense2d packing at step {}\n\n{} "
                                "atoms\n1 atom types\n{} {} xlo xhi\n{} {} ylo yhi\n-0.5 0.5 zlo "
                                "zhi\n\nAtoms # sphere\n\n",
                                sim.step_count(), p.size(), d.lo.x, d.hi.x, d.lo.y, d.hi.y);
  const double width = d.hi.x - d.lo.x;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = p.radius[i];
    double x = p.position[i].x;
    x -= width * std::floor((x - d.lo.x) / width); // into the periodic box
    out += fmt::format("{} 1 {} {} {} {} 0\n", p.id[i] + 1, 2.0 * r,
                       p.mass[i] / (4.0 / 3.0 * std::numbers::pi * r * r * r), x, p.position[i].y);
  }
  out += "\nVelocities\n\n";
  for (std::size_t i = 0; i < p.size(); ++i)
    out += fmt::format("{} {} {} 0 0 0 {}\n", p.id[i] + 1, p.velocity[i].x, p.velocity[i].y,
                       p.angular_velocity[i]);
  return out;
}

// Runs LAMMPS on the same system; returns its seconds per particle-step (0 if it failed). With
// `data` (a file lammps_data wrote), LAMMPS times that packing; without, one it settles itself.
double run_lammps(const BenchOptions& o, std::size_t nx, std::size_t ny, const LammpsRun& how,
                  const std::string& data) {
  if (std::system("command -v lmp > /dev/null 2>&1") != 0) {
    fmt::print("lammps: `lmp` is not on the PATH (apt-get install lammps); skipped\n");
    return 0.0;
  }
  const fs::path dir = fs::absolute(fs::path(o.system.cache) / "lammps");
  fs::create_directories(dir);
  for (const char* f : {"lammps-settle.in", "lammps-bench.in"})
    fs::copy_file(fs::path(o.lammps_inputs) / f, dir / f, fs::copy_options::overwrite_existing);
  // the packing LAMMPS settles itself, with the laws of --laws (the thesis': in talus-lmp)
  const bool thesis = o.laws == "thesis";
  const std::string tag = thesis ? "_thesis" : "";
  const std::string vars =
      fmt::format("-var nx {} -var ny {}{}{}", nx, ny, thesis ? " -var tag " + tag : "",
                  data.empty() ? "" : fmt::format(" -var read read_data -var packing '{}'", data));
  if (data.empty() && !fs::exists(dir / fmt::format("settled{}_{}x{}.restart", tag, nx, ny))) {
    const std::string settle_with =
        thesis ? fmt::format("{} -var pair 'granthesis hertz coulomb' -var coeff '{}'", talus_lmp(),
                             pair_coefficient_words(dense2d_thesis_material()))
               : std::string("lmp");
    fmt::print("lammps: settling its own packing (lammps-settle.in)...\n");
    std::fflush(stdout);
    if (std::system(fmt::format("cd '{}' && OMP_NUM_THREADS=1 {} -in lammps-settle.in {} -log "
                                "settle{}.log > settle{}.out 2>&1",
                                dir.string(), settle_with, vars, tag, tag)
                        .c_str()) != 0) {
      fmt::print("lammps: settling failed; see {}/settle{}.out\n", dir.string(), tag);
      return 0.0;
    }
  }
  std::string name = how.label; // a file name: "gran/hooke" -> "gran-hooke"
  std::replace(name.begin(), name.end(), '/', '-');
  std::string law;
  if (!how.pair.empty()) law = fmt::format("-var pair '{}' -var coeff '{}'", how.pair, how.coeff);
  const std::string mpi = mpirun_prefix(how.ranks);
  if (std::system(fmt::format("cd '{}' && OMP_NUM_THREADS=1 {}{} -in lammps-bench.in {} {} -var "
                              "nsteps {} -log bench-{}.log > bench-{}.out 2>&1",
                              dir.string(), mpi, how.program, vars, law, o.steps, name, name)
                      .c_str()) != 0) {
    fmt::print("lammps ({}): the run failed; see {}/bench-{}.out\n", how.label, dir.string(), name);
    return 0.0;
  }
  return lammps_seconds_per_particle_step((dir / fmt::format("bench-{}.log", name)).string());
}

// talus and LAMMPS in turns, round after round: a slow minute of the host falls on both. The
// first talus round is timed already (`first`); each later one starts again from `warm`.
struct Rounds {
  std::vector<double> talus;
  std::vector<std::vector<double>> lammps; ///< per LAMMPS run, its rounds
};

Rounds time_rounds(const BenchOptions& o, const Simulation& sim, const SimulationState& warm,
                   double first, const std::vector<LammpsRun>& runs, std::size_t nx, std::size_t ny,
                   const std::string& data) {
  Rounds r{{first}, std::vector<std::vector<double>>(runs.size())};
  std::vector<bool> failed(runs.size(), false);
  for (int round = 0; round < o.rounds; ++round) {
    if (round > 0) {
      Simulation again = Simulation::restore(warm, sim.config());
      r.talus.push_back(time_steps(again, o.steps));
    }
    std::string line = fmt::format("  round {}: talus {:.2f} ns per particle-step", round + 1,
                                   1e9 * r.talus.back());
    for (std::size_t k = 0; k < runs.size(); ++k) {
      if (failed[k]) continue;
      const double l = run_lammps(o, nx, ny, runs[k], data);
      failed[k] = l <= 0.0; // it said why
      if (failed[k]) continue;
      r.lammps[k].push_back(l);
      line.append(
          fmt::format(", LAMMPS {} {:.2f} ({:.2f}x)", runs[k].label, 1e9 * l, l / r.talus.back()));
    }
    if (o.rounds > 1) {
      fmt::print("{}\n", line);
      std::fflush(stdout);
    }
  }
  return r;
}

// The LAMMPS figures: each run's median and its ratio to talus'; with the thesis' laws also
// granthesis with the linear law against LAMMPS' own gran/hooke, the same law.
void print_lammps(const BenchOptions& o, const Rounds& r, const std::vector<LammpsRun>& runs,
                  double per) {
  const std::string of = o.rounds > 1 ? " (medians)" : "";
  for (std::size_t k = 0; k < runs.size(); ++k) {
    if (r.lammps[k].empty()) continue;
    const double l = median(r.lammps[k]);
    fmt::print("  LAMMPS {} ns per particle-step: {:.2f} on {} rank(s); LAMMPS / talus {:.2f}{}\n",
               runs[k].label, l * 1e9, runs[k].ranks, l / per, of);
  }
  if (runs.size() == 3 && !r.lammps[1].empty() && !r.lammps[2].empty())
    fmt::print("  granthesis (linear) / gran/hooke, the same law: {:.2f}{}\n",
               median(r.lammps[1]) / median(r.lammps[2]), of);
}

void print_talus(const BenchOptions& o, const Simulation& sim, double per, std::size_t rounds,
                 double contacts, double bytes, double engine_bytes) {
  const double n = static_cast<double>(sim.world().particles.size());
  fmt::print("  ns per particle-step:       {:.2f}{}\n", per * 1e9,
             rounds > 1 ? fmt::format(" (median of {} rounds)", rounds) : "");
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
  fmt::print("  skin:                       {:.3g} mm ({})\n", 1e3 * sim.neighbours().skin,
             o.system.skin > 0.0 ? "--skin" : "automatic; --skin 0.001 is the LAMMPS input's");
}

void run_bench(const BenchOptions& o) {
  require(o.rounds >= 1, fmt::format("bench dense2d: --rounds {}; allowed: >= 1", o.rounds));
  require(o.laws == "hooke" || o.laws == "thesis",
          fmt::format("bench dense2d: --laws {}; allowed: hooke, thesis", o.laws));
  const std::size_t ny = bench_base_side(o.system, "bench dense2d"), nx = ny * o.system.tiles;
  BenchSystem system = o.system;
  system.thesis_laws = o.laws == "thesis";
  Simulation sim = bench_simulation(system, "bench dense2d");
  const double n = static_cast<double>(sim.world().particles.size());
  sim.run(100); // warm up: caches, first rebuild
  // the state timed, for LAMMPS to time too
  std::string data;
  if (o.lammps && o.system.tiles == 1 && o.lammps_packing == "native") {
    const fs::path dir = fs::absolute(fs::path(o.system.cache) / "lammps");
    fs::create_directories(dir);
    data = (dir / fmt::format("native{}_{}x{}.data", o.laws == "thesis" ? "_thesis" : "", nx, ny))
               .string();
    write_file_atomically(data, lammps_data(sim));
  }
  // every round times the same steps from this state (as LAMMPS' runs start from its restart)
  const SimulationState warm = o.rounds > 1 ? sim.state() : SimulationState{};
  const std::uint64_t builds_before = sim.neighbours().builds;
  const std::uint64_t choices_before = sim.candidate_choices();
  const std::uint64_t tests_before = sim.drift_tests();
  const double first = time_steps(sim, o.steps);
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
  const std::vector<LammpsRun> runs =
      with_lammps ? lammps_runs(o, std::max(1, sim.threads())) : std::vector<LammpsRun>{};
  const Rounds r = time_rounds(o, sim, warm, first, runs, nx, ny, data);
  const double per = median(r.talus);

  fmt::print("dense2d: {} disks ({} x {}), {} steps, {} thread(s), {} laws\n",
             sim.world().particles.size(), nx, ny, o.steps, sim.threads(),
             o.laws == "thesis" ? "the thesis' (hertz, coulomb)" : "LAMMPS' gran/hooke/history");
  print_talus(o, sim, per, r.talus.size(), contacts, bytes, engine_bytes);
  fmt::print("  neighbour-list rebuilds:    {} in {} steps\n", builds, o.steps);
  fmt::print("  contact candidates chosen:  {} times; drift tested against the build {} times\n",
             choices, tests);
  print_lammps(o, r, runs, per);
  const double lammps = runs.empty() || r.lammps[0].empty() ? 0.0 : median(r.lammps[0]);
  const std::string csv =
      append_result(o.results, {.benchmark = o.laws == "thesis" ? "dense2d_thesis" : "dense2d",
                                .n = sim.world().particles.size(),
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
                "also run LAMMPS (lmp; on as many MPI ranks as threads) on the same system and "
                "print the ratio");
  cmd->add_option("--laws", o->laws,
                  "contact laws: hooke (LAMMPS' gran/hooke/history, both engines) or thesis "
                  "(viscoelastic Hertz and the capped viscous friction; LAMMPS runs pair_style "
                  "granthesis in talus-lmp, and its own gran/hooke beside it)")
      ->capture_default_str()
      ->check(CLI::IsMember({"hooke", "thesis"}));
  add_shared_bench_options(*cmd, o->system, o->results,
                           "neighbour-list skin, m (0: automatic, as in a run; 0.001 is the "
                           "LAMMPS input's; the physics is the same)");
  cmd->add_option("--lammps-packing", o->lammps_packing,
                  "the packing LAMMPS times: native (the state the native engine times, as a "
                  "data file) or own (one LAMMPS settles itself from the same lattice, "
                  "lammps-settle.in)")
      ->capture_default_str()
      ->check(CLI::IsMember({"native", "own"}));
  cmd->add_option("--lammps-inputs", o->lammps_inputs,
                  "folder with lammps-settle.in and lammps-bench.in")
      ->capture_default_str();
  cmd->add_option("--settle-time", o->system.settle_time, "settling time, s")
      ->capture_default_str();
  cmd->callback([o] { run_bench(*o); });

  add_bench_linear_command(*bench);
  add_bench_threads_command(*bench);
  add_bench_laws_command(*bench);
  add_bench_cell_command(*bench);
  add_bench_chute_command(*bench);

  auto threads = std::make_shared<int>(1);
  CLI::App* thesis = bench->add_subcommand(
      "thesis",
      "the thesis' table 2.2 (1000 steps of 382 to 3885 disks at dt = 1e-6 s) beside talus");
  thesis->add_option("--threads", *threads, "threads (0: all cores)")->capture_default_str();
  thesis->callback([threads] { run_thesis_table(*threads); });
}

} // namespace talus::cli
