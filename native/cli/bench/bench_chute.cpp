// `talus bench chute`: the system of LAMMPS' chute benchmark in the native 3D engine, timed in
// turns with LAMMPS' own gran/hooke/history on the same state (inputs/chute-bench/README.md).
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "cli/bench/bench_system.hpp"
#include "engine3d/simulation3.hpp"
#include "io/checkpoint.hpp"
#include "io/checkpoint3.hpp"
#include "io/lammps_export3.hpp"
#include "io/lammps_words.hpp"
#include "scenario3d/chute_bench.hpp"
#include "talus/law_table.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

struct ChuteOptions {
  std::size_t n = 32000;
  std::uint64_t flow_steps = 50000;
  std::uint64_t steps = 1000;
  int rounds = 1;
  int threads = 1;
  std::uint64_t sort_every = 1000;
  std::size_t tile = 1;
  bool lammps = false;
  std::string law; ///< --steps-with: a tangential law to time in both steps

  std::string cache = "bench/cache";
  std::string results = "bench/results";
  std::string lammps_inputs;
};

// The state as a LAMMPS data file (atom_style sphere): type 1 the free spheres, type 2 the
// frozen base (in.chute's group bottom), each sphere's density giving its native mass.
std::string chute_data(const ChuteBench& c, const Scene3& scene) {
  const Spheres& p = scene.spheres;
  const Domain3& d = scene.domain;
  std::string out = fmt::format("LAMMPS data file: talus bench chute, {} spheres on a {} x {} "
                                "base\n\n{} atoms\n2 atom types\n\n",
                                p.size(), c.nx, c.ny, p.size());
  out += fmt::format("0 {} xlo xhi\n0 {} ylo yhi\n{} {} zlo zhi\n\n", exact(d.hi.x), exact(d.hi.y),
                     exact(d.lo.z), exact(d.hi.z));
  return out + sphere_data_sections(p, [&p](std::size_t i) { return p.is_free(i) ? 1 : 2; });
}

// LAMMPS on the data file, o.steps steps on `ranks` MPI ranks: seconds per particle-step, 0 if it
// could not run (it says why).
double run_lammps(const ChuteOptions& o, int ranks, const fs::path& dir, const std::string& data) {
  if (std::system("command -v lmp > /dev/null 2>&1") != 0) {
    fmt::print("lammps: `lmp` is not on the PATH (apt-get install lammps); skipped\n");
    return 0.0;
  }
  fs::copy_file(fs::path(o.lammps_inputs) / "in.chute", dir / "in.chute",
                fs::copy_options::overwrite_existing);
  const std::string command = fmt::format(
      "cd '{}' && OMP_NUM_THREADS=1 {}lmp -in in.chute -var data '{}' -var nsteps {} -log "
      "bench.log > bench.out 2>&1",
      dir.string(), mpirun_prefix(ranks), data, o.steps);
  if (std::system(command.c_str()) != 0) {
    fmt::print("lammps: the run failed; see {}/bench.out\n", dir.string());
    return 0.0;
  }
  return lammps_seconds_per_particle_step((dir / "bench.log").string());
}

// Seconds per particle-step of `steps` steps from `state` (in the general step if `general`);
// the engine's bytes after them (its buffers sized by the steps) into `bytes`.
double time_native(const SimulationState3& state, const Settings3& settings, std::uint64_t steps,
                   std::size_t& bytes, bool general = false) {
  Simulation3 sim = Simulation3::restore(state, settings);
  sim.use_general_step(general);
  const auto start = std::chrono::steady_clock::now();
  sim.run(steps);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  bytes = sim.footprint_bytes();
  return seconds / (static_cast<double>(sim.scene().spheres.size()) * static_cast<double>(steps));
}

void print_system(const ChuteOptions& o, const ChuteBench& c, const Simulation3& sim) {
  const double n = static_cast<double>(sim.scene().spheres.size());
  fmt::print("bench chute: {} spheres ({} x {} frozen base, {} layers above), gran/hooke/history "
             "of in.chute, {} thread(s), {} round(s) of {} steps after {} steps of flow\n",
             sim.scene().spheres.size(), c.nx, c.ny, c.layers, sim.threads(), o.rounds, o.steps,
             o.flow_steps);
  fmt::print("  pair contacts:              {} at a time ({})\n", pair_contact_lanes(),
             pair_contact_lanes() == 4 ? "AVX2" : "SSE2");
  fmt::print("  contacts per free sphere:   {:.3f}\n", sim.coordination());
  fmt::print("  list entries per sphere:    {:.3f} (half list)\n",
             static_cast<double>(sim.list().pair_count()) / n);
}

// The state after o.flow_steps of flow: from the cache, or run now (and cached).
SimulationState3 flowed_state(const ChuteOptions& o, const ChuteBench& c) {
  const fs::path file =
      fs::path(o.cache) / "chute" / fmt::format("chute_{}_{}steps.ckpt3", o.n, o.flow_steps);
  if (fs::exists(file)) {
    try {
      Checkpoint3 saved = decode_checkpoint3(read_file(file.string()), file.string());
      fmt::print("flowing layer from {}\n", file.string());
      return std::move(saved.state);
    } catch (const CheckpointError& e) {
      fmt::print("cache unusable ({}); letting it flow again\n", e.what());
    }
  }
  fmt::print("letting the layer flow for {} steps...\n", o.flow_steps);
  std::fflush(stdout);
  Simulation3 sim(c.scene, c.settings);
  sim.run(o.flow_steps);
  fs::create_directories(file.parent_path());
  write_file_atomically(file.string(), encode_checkpoint3({sim.state(), c.settings, ""}));
  return sim.state();
}

// Steps after a tiling, before the timed state: the springs, which a tiling does not carry,
// loaded again (several collision times of the chute's contacts).
constexpr std::uint64_t tile_settle_steps = 200;

// The flowed state repeated o.tile x o.tile across the slope, settled tile_settle_steps; c's base
// counts as the tiled one's.
SimulationState3 tiled_state(const ChuteOptions& o, ChuteBench& c, const SimulationState3& state) {
  const Simulation3 flowed = Simulation3::restore(state, c.settings);
  fmt::print("tiled {} x {} across the slope, then {} steps for the springs to load again\n",
             o.tile, o.tile, tile_settle_steps);
  std::fflush(stdout);
  Simulation3 sim(tiled_across(flowed.scene(), o.tile), c.settings);
  sim.run(tile_settle_steps);
  c.nx *= o.tile, c.ny *= o.tile;
  return sim.state();
}

// --steps-with LAW: the flowing layer with the tangential law LAW (`none`: its spins stopped, so
// that nothing turns; `coulomb`: damped at in.chute's gamma_n, which its dashpot has none of),
// timed in the step specialised to it and in the general step, in turns.
void run_both_steps(const ChuteOptions& o, ChuteBench& c, SimulationState3 state) {
  c.settings.tangential_law = parse_tangential_law(o.law);
  if (c.settings.tangential_law == law_id<Frictionless>)
    for (Vec3& w : state.scene.spheres.angular_velocity) w = {};
  for (Material& m : state.scene.materials) m.tangential_damping = m.normal_damping_rate;
  const Simulation3 sim = Simulation3::restore(state, c.settings);
  fmt::print("bench chute --steps-with {}: {} spheres, the flowing layer, {} thread(s), {} "
             "round(s) of {} steps in each step, in turns; the step specialised to it: {}\n",
             o.law, sim.scene().spheres.size(), sim.threads(), o.rounds, o.steps,
             sim.step_description());
  std::vector<double> special, general, ratio;
  std::size_t bytes = 0, bytes_general = 0;
  for (int round = 0; round < o.rounds; ++round) {
    special.push_back(time_native(state, c.settings, o.steps, bytes));
    general.push_back(time_native(state, c.settings, o.steps, bytes_general, true));
    ratio.push_back(general.back() / special.back());
    fmt::print("  round {}: specialised {:.2f} ns per particle-step, general {:.2f} ({:.2f}x)\n",
               round + 1, 1e9 * special.back(), 1e9 * general.back(), ratio.back());
    std::fflush(stdout);
  }
  fmt::print("  the specialised step against the general one: {:.2f}x (median of the rounds' "
             "ratios)\n",
             median(ratio));
  const double n = static_cast<double>(sim.scene().spheres.size());
  fmt::print("  engine memory per sphere:   {:.0f} bytes, general {:.0f}\n",
             static_cast<double>(bytes) / n, static_cast<double>(bytes_general) / n);
  for (const bool g : {false, true}) {
    const std::string file = append_result(
        o.results, {.benchmark = "chute_" + o.law + (g ? "_general" : ""),
                    .n = sim.scene().spheres.size(),
                    .steps = o.steps,
                    .threads = sim.threads(),
                    .seconds_per_particle_step = median(g ? general : special),
                    .contacts_per_particle = sim.coordination(),
                    .peak_bytes_per_particle = peak_rss_bytes() / n,
                    .nx = c.nx,
                    .ny = c.ny,
                    .engine_bytes_per_particle = static_cast<double>(g ? bytes_general : bytes) / n,
                    .skin = c.settings.skin});
    if (g) fmt::print("appended to {}\n", file);
  }
}

void run_chute(const ChuteOptions& o) {
  ChuteBench c = build_chute_bench(o.n);
  c.settings.threads = o.threads;
  c.settings.sort_interval = o.sort_every;
  SimulationState3 state = flowed_state(o, c);
  if (o.tile > 1) state = tiled_state(o, c, state);
  if (!o.law.empty()) return run_both_steps(o, c, std::move(state));
  const Simulation3 sim = Simulation3::restore(state, c.settings);
  print_system(o, c, sim);
  const fs::path dir = fs::absolute(fs::path(o.cache) / "chute");
  const std::string data = fmt::format("chute_{}.data", sim.scene().spheres.size());
  if (o.lammps) {
    fs::create_directories(dir);
    write_file_atomically((dir / data).string(), chute_data(c, sim.scene()));
  }
  std::vector<double> native, lammps;
  std::size_t engine_bytes = 0;
  for (int round = 0; round < o.rounds; ++round) {
    native.push_back(time_native(state, c.settings, o.steps, engine_bytes));
    std::string line = fmt::format("  round {}: talus {:.2f} ns per particle-step", round + 1,
                                   1e9 * native.back());
    if (o.lammps && (round == 0 || !lammps.empty())) {
      const double l = run_lammps(o, sim.threads(), dir, data);
      if (l > 0.0) {
        lammps.push_back(l);
        line += fmt::format(", LAMMPS {:.2f} ({:.2f}x)", 1e9 * l, l / native.back());
      }
    }
    fmt::print("{}\n", line);
    std::fflush(stdout);
  }
  const double n = static_cast<double>(sim.scene().spheres.size());
  const double per = median(native), per_lammps = lammps.empty() ? 0.0 : median(lammps);
  const double engine = static_cast<double>(engine_bytes) / n;
  fmt::print("  ns per particle-step:       {:.2f} (median)\n", 1e9 * per);
  fmt::print("  engine memory per sphere:   {:.0f} bytes (state, list, springs, buffers)\n",
             engine);
  fmt::print("  peak memory per sphere:     {:.0f} bytes (the process' peak resident size)\n",
             peak_rss_bytes() / n);
  if (per_lammps > 0.0)
    fmt::print("  LAMMPS gran/hooke/history:  {:.2f} ns per particle-step on {} rank(s); "
               "LAMMPS / talus {:.2f} (medians)\n",
               1e9 * per_lammps, sim.threads(), per_lammps / per);
  const std::string file =
      append_result(o.results, {.benchmark = "chute",
                                .n = sim.scene().spheres.size(),
                                .steps = o.steps,
                                .threads = sim.threads(),
                                .seconds_per_particle_step = per,
                                .contacts_per_particle = sim.coordination(),
                                .peak_bytes_per_particle = peak_rss_bytes() / n,
                                .lammps_seconds_per_particle_step = per_lammps,
                                .nx = c.nx,
                                .ny = c.ny,
                                .engine_bytes_per_particle = engine,
                                .skin = c.settings.skin});
  fmt::print("appended to {}\n", file);
}

} // namespace

void add_bench_chute_command(CLI::App& bench) {
  auto o = std::make_shared<ChuteOptions>();
  o->lammps_inputs = std::string(TALUS_SOURCE_DIR) + "/inputs/chute-bench";
  CLI::App* cmd = bench.add_subcommand(
      "chute", "LAMMPS' chute benchmark in 3D: spheres flowing down a rough base at 26 degrees, "
               "gran/hooke/history, periodic in x and y (inputs/chute-bench/README.md)");
  cmd->add_option("--n", o->n, "spheres (about; the base is 2k x k, 40 layers with it)")
      ->capture_default_str()
      ->check(CLI::Range(1, 4000000));
  cmd->add_option("--flow-steps", o->flow_steps, "steps of flow before the timed state")
      ->capture_default_str()
      ->check(CLI::Range(0, 100000000));
  cmd->add_option("--steps", o->steps, "timed steps per round")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000000));
  cmd->add_option("--rounds", o->rounds,
                  "times the steps are timed from the same state, in turns with LAMMPS if "
                  "--lammps: the figures are the medians")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--threads", o->threads, "threads (0: all cores); LAMMPS' MPI ranks")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  cmd->add_option("--sort-every", o->sort_every,
                  "steps between renumberings of the spheres in the order of their cells (0: "
                  "never); LAMMPS sorts its atoms every 1000 steps")
      ->capture_default_str()
      ->check(CLI::Range(0, 100000000));
  cmd->add_option("--tile", o->tile,
                  "time the flowing layer repeated K x K across the slope (K^2 times the "
                  "spheres; its springs loaded again first): the cost against size "
                  "beyond what a flow of its own would take long to reach")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  CLI::Option* lammps =
      cmd->add_flag("--lammps", o->lammps,
                    "also time LAMMPS (lmp, gran/hooke/history) on the same state, in turns");
  cmd->add_option("--steps-with", o->law,
                  "time the flowing layer with this tangential law (none: the spins stopped; "
                  "coulomb: damped at gamma_n) in the step specialised to it and in the general "
                  "step, in turns")
      ->check(CLI::IsMember(
          std::vector<std::string>(TangentialLaws::names.begin(), TangentialLaws::names.end())))
      ->excludes(lammps);
  cmd->add_option("--cache", o->cache,
                  "folder for the flowing layer (cached) and LAMMPS' data file and logs")
      ->capture_default_str();
  cmd->add_option("--results", o->results, "folder of the results CSV")->capture_default_str();
  cmd->add_option("--lammps-inputs", o->lammps_inputs, "folder with in.chute")
      ->capture_default_str();
  cmd->callback([o] { run_chute(*o); });
}

} // namespace talus::cli
