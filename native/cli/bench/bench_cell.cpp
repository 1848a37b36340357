// `talus bench cell`: what a deforming periodic cell costs per particle-step. One packing of
// frictionless disks, pressed by a cell held at a pressure, is timed three ways in turns: held at
// the pressure (the controller reads the contacts every step), at a strain rate of 0 (the remap
// alone) and with no cell at all.
#include <memory>
#include <vector>

#include <fmt/core.h>

#include "analysis/observables.hpp"
#include "cli/bench/bench_system.hpp"
#include "core/random.hpp"
#include "talus/error.hpp"

namespace talus::cli {

namespace {

struct CellOptions {
  int side = 100; ///< disks per row of the starting lattice
  int rounds = 3;
  std::uint64_t steps = 2000;
  int threads = 1;
  std::string results = "bench/results";
};

// side^2 frictionless disks of radius 4 to 6 mm, pressed by a cell to 100 N/m from a lattice
// of pitch 12 mm (a packing fraction of 0.55) for 0.4 s.
SimulationState jammed(const CellOptions& o, SimulationConfig& config) {
  World w;
  Material m;
  m.density = 2650.0;
  m.normal_stiffness = 1.0e5;
  m.normal_damping_rate = 50.0;
  m.friction = 0.0;
  w.materials = {m};
  w.gravity = {0.0, 0.0};
  const double pitch = 0.012, side = pitch * o.side;
  w.domain = {{0.0, 0.0}, {side, side}, true, true};
  RandomStream rng(11, 1);
  for (int y = 0; y < o.side; ++y)
    for (int x = 0; x < o.side; ++x)
      w.add_particle({.position = {pitch * (x + 0.5), pitch * (y + 0.5)},
                      .radius = 0.004 + 0.002 * rng.uniform()});
  Driver d;
  d.motion = Cell{.pressure = 100.0, .max_strain_rate = 2.0};
  w.drivers.push_back(d);
  config.timestep = 1e-5;
  config.tangential_law = law_id<Frictionless>;
  config.threads = o.threads;
  Simulation s(std::move(w), config);
  s.run(40'000); // 0.4 s: the cell has shrunk onto the disks
  return s.state();
}

void run_cell(const CellOptions& o) {
  SimulationConfig config;
  const SimulationState state = jammed(o, config);
  const char* names[] = {"pressure", "strain rate 0", "no cell"};
  std::vector<TimedRun> runs;
  for (int mode = 0; mode < 3; ++mode) {
    SimulationState copy = state;
    if (mode == 1) copy.world.drivers.front().motion = Cell{};
    if (mode == 2) copy.world.drivers.clear();
    TimedRun r;
    r.sim = std::make_unique<Simulation>(Simulation::restore(std::move(copy), config));
    r.steps = o.steps;
    r.sim->run(100); // warm up
    runs.push_back(std::move(r));
  }
  const Simulation& first = *runs.front().sim;
  const double n = static_cast<double>(first.world().particles.size());
  fmt::print("bench cell: {} frictionless disks pressed by a cell to 100 N/m, packing fraction "
             "{:.3f}, {:.2f} contacts per disk, {} thread(s), {} round(s) of {} steps\n",
             first.world().particles.size(),
             packing_fraction(first, first.world().domain.lo, first.world().domain.hi),
             2.0 * static_cast<double>(contact_count(first)) / n, first.threads(), o.rounds,
             o.steps);
  time_in_turns(runs, o.rounds);
  fmt::print("| cell | ns per particle-step (median) | against no cell |\n|---|---|---|\n");
  const double none = median(runs[2].ns);
  for (int mode = 0; mode < 3; ++mode) {
    const double m = median(runs[static_cast<std::size_t>(mode)].ns);
    fmt::print("| {} | {:.2f} | {:.2f} |\n", names[mode], m, m / none);
    append_result(o.results,
                  {.benchmark = fmt::format("cell_{}", mode == 0   ? "pressure"
                                                       : mode == 1 ? "rate"
                                                                   : "none"),
                   .n = first.world().particles.size(),
                   .steps = o.steps,
                   .threads = first.threads(),
                   .seconds_per_particle_step = 1e-9 * m,
                   .contacts_per_particle = 2.0 * static_cast<double>(contact_count(first)) / n});
  }
}

} // namespace

void add_bench_cell_command(CLI::App& bench) {
  auto o = std::make_shared<CellOptions>();
  CLI::App* cmd = bench.add_subcommand(
      "cell", "the cost per particle-step of a deforming cell: held at a pressure, at a rate, "
              "and none, on one packing, timed in turns");
  cmd->add_option("--side", o->side, "disks per row of the starting lattice")
      ->capture_default_str()
      ->check(CLI::Range(10, 2000));
  cmd->add_option("--rounds", o->rounds, "times every case is timed, in turns")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--steps", o->steps, "steps per case and round")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000000));
  cmd->add_option("--threads", o->threads, "threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  cmd->add_option("--results", o->results, "folder of the results CSV")->capture_default_str();
  cmd->callback([o] { run_cell(*o); });
}

} // namespace talus::cli
