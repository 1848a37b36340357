// `talus bench threads`: the speed-up of more threads on one system. One settled dense2d system,
// copied once per thread count, every copy timed in turns, round after round (time_in_turns):
// the copies stay in the same state, since results do not depend on the thread count (checked
// here at the end, bit for bit), and a drift of the machine's speed slows them alike.
#include <algorithm>
#include <csignal>
#include <memory>
#include <vector>

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "analysis/observables.hpp"
#include "cli/bench/bench_system.hpp"
#include "talus/error.hpp"

namespace talus::cli {

namespace {

struct ThreadsOptions {
  BenchSystem system{.n = 100000};
  std::vector<int> threads{1, 2};
  std::uint64_t steps = 1000; // per copy and round
  int rounds = 5;
  std::string results = "bench/results";
  bool busy = false; ///< time beside another process that keeps a core busy
};

// A process that keeps one core busy until it is killed (and ends with its parent).
pid_t start_busy_process() {
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  require(pid >= 0, "bench threads --busy: fork failed");
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(0);
    volatile std::uint64_t spins = 0; // volatile: the loop is not optimised away
    for (;;) spins = spins + 1;
  }
  return pid;
}

// Every field that decides how a run goes on, bit for bit.
bool same_state(const Simulation& a, const Simulation& b) {
  const Particles &p = a.world().particles, &q = b.world().particles;
  return a.step_count() == b.step_count() && p.id == q.id && p.position == q.position &&
         p.velocity == q.velocity && p.angle == q.angle &&
         p.angular_velocity == q.angular_velocity && p.force == q.force && p.torque == q.torque &&
         a.neighbours().neighbour == b.neighbours().neighbour &&
         a.neighbours().history == b.neighbours().history &&
         a.neighbours().wall_history == b.neighbours().wall_history;
}

void run_threads(const ThreadsOptions& o) {
  require(o.rounds >= 1, fmt::format("bench threads: --rounds {}; allowed: >= 1", o.rounds));
  require(!o.threads.empty(), "bench threads: --threads is empty; allowed: counts >= 1");
  const std::size_t ny = bench_base_side(o.system, "bench threads"), nx = ny * o.system.tiles;
  const Simulation base = bench_simulation(o.system, "bench threads");
  std::vector<TimedRun> runs;
  for (const int t : o.threads) {
    require(t >= 1, fmt::format("bench threads: --threads holds {}; allowed: counts >= 1", t));
    SimulationConfig config = base.config();
    config.threads = t;
    config.min_particles_per_thread = 1; // the count asked for, however small the system
    TimedRun z;
    z.sim = std::make_unique<Simulation>(Simulation::restore(base.state(), config));
    z.steps = o.steps;
    z.sim->run(100); // warm up: caches, first rebuild
    runs.push_back(std::move(z));
  }
  fmt::print("bench threads: {} disks ({} x {}), {} steps per round, {} round(s)\n",
             base.world().particles.size(), nx, ny, o.steps, o.rounds);
  fmt::print("  (each round: {} thread(s)){}\n", fmt::join(o.threads, ", "),
             o.busy ? "; beside another process that keeps one core busy" : "");
  const pid_t busy = o.busy ? start_busy_process() : 0;
  time_in_turns(runs, o.rounds);
  if (busy > 0) {
    ::kill(busy, SIGKILL);
    ::waitpid(busy, nullptr, 0);
  }
  const double first = median(runs.front().ns);
  // Two figures for the speed-up: the ratio of the medians, and the median of the rounds' own
  // ratios (each round's copies ran within seconds of each other, so a slow minute of the host
  // slows both sides of a round's ratio, where it moves one median only).
  fmt::print("| threads | ns per particle-step (median) | min | max | throughput / {} thread(s) "
             "| median of the rounds' speed-ups |\n|---|---|---|---|---|---|\n",
             runs.front().sim->threads());
  const double n = static_cast<double>(base.world().particles.size());
  const double contacts = 2.0 * static_cast<double>(contact_count(*runs.front().sim)) / n;
  std::string csv;
  for (const TimedRun& z : runs) {
    const double m = median(z.ns);
    std::vector<double> speed_up;
    for (std::size_t r = 0; r < z.ns.size(); ++r) speed_up.push_back(runs.front().ns[r] / z.ns[r]);
    fmt::print("| {} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} |\n", z.sim->threads(), m,
               *std::min_element(z.ns.begin(), z.ns.end()),
               *std::max_element(z.ns.begin(), z.ns.end()), first / m, median(speed_up));
    csv = append_result(
        o.results, {.benchmark = o.busy ? "dense2d_threads_busy" : "dense2d_threads",
                    .n = base.world().particles.size(),
                    .steps = z.steps,
                    .threads = z.sim->threads(),
                    .seconds_per_particle_step = 1e-9 * m,
                    .contacts_per_particle = contacts,
                    .nx = nx,
                    .ny = ny,
                    .engine_bytes_per_particle = static_cast<double>(z.sim->footprint_bytes()) / n,
                    .skin = z.sim->neighbours().skin});
  }
  bool identical = true;
  for (const TimedRun& z : runs) identical = identical && same_state(*runs.front().sim, *z.sim);
  fmt::print("states at step {} bit-identical for every thread count: {}\n",
             runs.front().sim->step_count(), identical ? "yes" : "NO");
  fmt::print("appended to {} (benchmark dense2d_threads: the medians; bytes_per_particle 0, not "
             "measured with several systems in one process)\n",
             csv);
  require(identical, "bench threads: the thread counts gave different states");
}

} // namespace

void add_bench_threads_command(CLI::App& bench) {
  auto o = std::make_shared<ThreadsOptions>();
  CLI::App* cmd = bench.add_subcommand(
      "threads", "the speed-up of more threads on one dense2d system (a copy per thread count, "
                 "timed in turns, medians of rounds, states compared bit for bit)");
  cmd->add_option("--n", o->system.n, "number of disks (rounded to a square)")
      ->capture_default_str()
      ->check(CLI::Range(9, 100000000));
  cmd->add_option("--tiles", o->system.tiles,
                  "copies side by side of the settled square packing of n / tiles disks")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--threads", o->threads, "thread counts, one copy of the system each")
      ->capture_default_str()
      ->delimiter(',')
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--steps", o->steps, "steps per copy and round")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000000));
  cmd->add_option("--rounds", o->rounds, "times every copy is timed, in turns")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  add_shared_bench_options(*cmd, o->system, o->results);
  cmd->add_flag("--busy", o->busy,
                "time beside another process that keeps one core busy (a shared machine); a run "
                "then takes the faster of its threads and one");
  cmd->callback([o] { run_threads(*o); });
}

} // namespace talus::cli
