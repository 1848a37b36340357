#pragma once
// What the benchmarks share: the settled dense2d system (cached between runs, tiled for large
// N), the machine's name and the results CSV of bench/results/<machine>.csv.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "simulation/simulation.hpp"

namespace talus::cli {

/// How a benchmark's dense2d system is made.
struct BenchSystem {
  std::size_t n = 10000;
  std::size_t tiles = 1;           ///< copies side by side of the settled packing of n / tiles
  double skin = 0.0;               ///< m; 0: automatic (the engine's default)
  std::uint64_t sort_every = 1000; ///< steps between renumberings (the scenarios' default)
  int threads = 1;
  double settle_time = 0.6; ///< s, as lammps-settle.in
  bool thesis_laws = false; ///< settled and timed with the thesis' laws (use_thesis_laws)
  std::string cache = "bench/cache";
};

/// The side of the square base packing for n / tiles disks, refused (InvalidArgument, naming
/// `command`) below 3 x 3.
std::size_t bench_base_side(const BenchSystem& s, const std::string& command);

/// The settled system, ready to time: the packing from the cache (settled and cached first if
/// it is not there), tiled, its list to be rebuilt at the first step with s.skin.
Simulation bench_simulation(const BenchSystem& s, const std::string& command);

/// "Intel_R__Xeon_R__Processor-2cores": the CPU model and core count, as a file name.
std::string machine_name();

/// The process' peak resident memory, bytes.
double peak_rss_bytes();

/// One row of the results CSV (its columns: results_header()).
struct ResultRow {
  std::string benchmark = "dense2d";
  std::size_t n = 0;
  std::uint64_t steps = 0;
  int threads = 1;
  double seconds_per_particle_step = 0.0;
  double contacts_per_particle = 0.0;
  double peak_bytes_per_particle = 0.0;
  double lammps_seconds_per_particle_step = 0.0; ///< 0: not run
  std::size_t nx = 0, ny = 0;
  double engine_bytes_per_particle = 0.0;
  double skin = 0.0; ///< m
};

/// Appends `row` to folder/<machine>.csv (with a header if the file is new); returns the path.
std::string append_result(const std::string& folder, const ResultRow& row);

/// Runs `steps` steps of `sim` and returns the wall-clock seconds per particle-step.
double time_steps(Simulation& sim, std::uint64_t steps);

/// One of the systems that time_in_turns times.
struct TimedRun {
  std::unique_ptr<Simulation> sim;
  std::uint64_t steps = 0;  ///< per round
  std::vector<double> ns;   ///< ns per particle-step, one figure per round
  std::uint64_t builds = 0; ///< neighbour-list builds while timed
};

/// Times every run for its steps, in turns, `rounds` times (every other round in the opposite
/// order, so that a drift of the machine's speed within a round does not favour the runs timed
/// first), and prints each round's figures on a line. On a shared host whose speed moves from
/// minute to minute this slows every run alike, where separate invocations would not.
void time_in_turns(std::vector<TimedRun>& runs, int rounds);

/// The command prefix that runs a program on `ranks` MPI ranks as root (Open MPI's consent
/// variables, --oversubscribe); empty for one rank.
std::string mpirun_prefix(int ranks);

/// Seconds per particle-step from the "Loop time of T on P procs for S steps with N atoms" line
/// of a LAMMPS log; 0 (and a line saying so) where the file has none.
double lammps_seconds_per_particle_step(const std::string& log_file);

/// The median of v (not empty).
double median(std::vector<double> v);

/// Registers the options every dense2d benchmark takes: --skin (with `skin_help`), --cache and
/// --results.
void add_shared_bench_options(
    CLI::App& cmd, BenchSystem& s, std::string& results,
    const std::string& skin_help = "neighbour-list skin, m (0: automatic)");

/// `talus bench chute` (cli/bench/bench_chute.cpp): LAMMPS' chute benchmark system in 3D.
void add_bench_chute_command(CLI::App& bench);
/// `talus bench linear` (cli/bench_linear.cpp) and `talus bench threads` (cli/bench_threads.cpp),
/// under the `bench` command.
void add_bench_linear_command(CLI::App& bench);
void add_bench_threads_command(CLI::App& bench);
void add_bench_cell_command(CLI::App& bench);
/// `talus bench laws` (cli/bench_laws.cpp).
void add_bench_laws_command(CLI::App& bench);

} // namespace talus::cli
