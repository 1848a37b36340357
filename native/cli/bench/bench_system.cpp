#include "cli/bench/bench_system.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sys/resource.h>
#include <thread>

#include <fmt/chrono.h>
#include <fmt/core.h>

#include "io/checkpoint.hpp"
#include "scenario/dense2d.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

std::size_t side(std::size_t n) {
  return static_cast<std::size_t>(std::llround(std::sqrt(static_cast<double>(n))));
}

// The settled square packing, from the cache or settled now (and cached).
SimulationState settled_state(const BenchSystem& s, std::size_t side, SimulationConfig& config) {
  Dense2d d = build_dense2d(side, side);
  if (s.thesis_laws) use_thesis_laws(d.world, d.config);
  config = d.config;
  config.threads = s.threads;
  // a packing settled for another time than the default 0.6 s, or with other laws, is cached
  // apart
  const std::string laws = s.thesis_laws ? "_thesis" : "";
  const std::string name =
      s.settle_time == BenchSystem{}.settle_time
          ? fmt::format("dense2d{}_{}x{}.ckpt", laws, side, side)
          : fmt::format("dense2d{}_{}x{}_{}s.ckpt", laws, side, side, s.settle_time);
  const fs::path file = fs::path(s.cache) / name;
  if (fs::exists(file)) {
    try {
      Checkpoint c = decode_checkpoint(read_file(file.string()), file.string());
      fmt::print("settled packing from {}\n", file.string());
      return std::move(c.state);
    } catch (const CheckpointError& e) {
      fmt::print("cache unusable ({}); settling again\n", e.what());
    }
  }
  fmt::print("settling {} x {} disks for {} s ({} steps)...\n", side, side, s.settle_time,
             static_cast<std::uint64_t>(s.settle_time / config.timestep));
  std::fflush(stdout);
  Simulation sim(std::move(d.world), config);
  sim.run(static_cast<std::uint64_t>(std::llround(s.settle_time / config.timestep)));
  fs::create_directories(s.cache);
  write_file_atomically(file.string(), encode_checkpoint({sim.state(), sim.config(), ""}));
  return sim.state();
}

} // namespace

std::size_t bench_base_side(const BenchSystem& s, const std::string& command) {
  const std::size_t ny = side(s.n / s.tiles);
  require(ny >= 3, fmt::format("{}: --n {} / --tiles {} leaves a base packing of {} x {} disks; "
                               "allowed: n / tiles >= 9",
                               command, s.n, s.tiles, ny, ny));
  return ny;
}

Simulation bench_simulation(const BenchSystem& s, const std::string& command) {
  const std::size_t ny = bench_base_side(s, command);
  SimulationConfig config;
  SimulationState state = settled_state(s, ny, config);
  if (s.tiles > 1) state = tile_dense2d(state, s.tiles, config.skin);
  // the list is rebuilt at the first step, with the given skin or the automatic one (the
  // cached packing's list has the LAMMPS input's 1 mm)
  config.skin = s.skin;
  config.sort_interval = s.sort_every;
  config.threads = s.threads;
  state.neighbours.reference.clear();
  return Simulation::restore(std::move(state), config);
}

std::string machine_name() {
  std::ifstream cpu("/proc/cpuinfo");
  std::string line, model = "unknown-cpu";
  while (std::getline(cpu, line))
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  std::string name = model + "-" + std::to_string(std::thread::hardware_concurrency()) + "cores";
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '_';
  return name;
}

double peak_rss_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) * 1024.0;
}

std::string append_result(const std::string& folder, const ResultRow& r) {
  fs::create_directories(folder);
  const fs::path csv = fs::path(folder) / (machine_name() + ".csv");
  const bool fresh = !fs::exists(csv);
  std::ofstream out(csv, std::ios::app);
  if (fresh)
    out << "date,talus_version,benchmark,n,steps,threads,ns_per_particle_step,"
           "particle_steps_per_second,contacts_per_particle,bytes_per_particle,"
           "lammps_ns_per_particle_step,lammps_over_talus,nx,ny,engine_bytes_per_particle,skin_m\n";
  const double per = r.seconds_per_particle_step, lammps = r.lammps_seconds_per_particle_step;
  out << fmt::format("{:%Y-%m-%dT%H:%M:%S},{},{},{},{},{},{:.3f},{:.6g},{:.3f},{:.0f},{},{},{}"
                     ",{},{:.0f},{}\n",
                     fmt::gmtime(std::time(nullptr)), TALUS_VERSION, r.benchmark, r.n, r.steps,
                     r.threads, per * 1e9, 1.0 / per, r.contacts_per_particle,
                     r.peak_bytes_per_particle,
                     lammps > 0 ? fmt::format("{:.3f}", lammps * 1e9) : "",
                     lammps > 0 ? fmt::format("{:.3f}", lammps / per) : "", r.nx, r.ny,
                     r.engine_bytes_per_particle, r.skin);
  return csv.string();
}

void add_shared_bench_options(CLI::App& cmd, BenchSystem& s, std::string& results,
                              const std::string& skin_help) {
  cmd.add_option("--skin", s.skin, skin_help)->capture_default_str()->check(CLI::Range(0.0, 0.01));
  cmd.add_option("--cache", s.cache, "folder for settled packings")->capture_default_str();
  cmd.add_option("--results", results, "folder for the results CSV")->capture_default_str();
}

double time_steps(Simulation& sim, std::uint64_t steps) {
  const auto start = std::chrono::steady_clock::now();
  sim.run(steps);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return seconds / (static_cast<double>(sim.world().particles.size()) * static_cast<double>(steps));
}

void time_in_turns(std::vector<TimedRun>& runs, int rounds) {
  for (int r = 0; r < rounds; ++r) {
    for (std::size_t q = 0; q < runs.size(); ++q) {
      TimedRun& z = runs[r % 2 == 0 ? q : runs.size() - 1 - q];
      const std::uint64_t builds = z.sim->neighbours().builds;
      z.ns.push_back(1e9 * time_steps(*z.sim, z.steps));
      z.builds += z.sim->neighbours().builds - builds;
    }
    fmt::print("  round {}:", r + 1);
    for (const TimedRun& z : runs) fmt::print(" {:.2f}", z.ns.back());
    fmt::print(" ns per particle-step\n");
    std::fflush(stdout);
  }
}

std::string mpirun_prefix(int ranks) {
  if (ranks <= 1) return {};
  return fmt::format("env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun "
                     "--oversubscribe -np {} ",
                     ranks);
}

double lammps_seconds_per_particle_step(const std::string& log_file) {
  const std::string log = read_file(log_file);
  const auto at = log.find("Loop time of ");
  double seconds = 0.0, steps = 0.0, atoms = 0.0;
  int procs = 0;
  if (at == std::string::npos ||
      std::sscanf(log.c_str() + at, "Loop time of %lf on %d procs for %lf steps with %lf atoms",
                  &seconds, &procs, &steps, &atoms) != 4 ||
      steps <= 0 || atoms <= 0) {
    fmt::print("lammps: no 'Loop time' in {}\n", log_file);
    return 0.0;
  }
  return seconds / (steps * atoms);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 == 1 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

} // namespace talus::cli
