// `talus demo`: polydisperse grains poured into a box settle under gravity; energy and
// coordination are printed as they go and written to a run folder.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/core.h>
#include <fmt/os.h>

#include "analysis/observables.hpp"
#include "cli/commands.hpp"
#include "render/snapshot_png.hpp"
#include "scenario/pour_box.hpp"
#include "talus/error.hpp"

namespace talus::cli {

namespace {

struct DemoOptions {
  std::size_t count = 2000;
  double duration = 1.5;
  std::string out = "runs/demo";
  int threads = 0;
  std::string integrator = "gear";
  std::uint64_t seed = 1;
  double settle_ratio = 1.0e-6;
  int lines = 15;
};

// Writes `text` to path through a temporary file and a rename, so no half-written file remains.
void write_atomically(const std::filesystem::path& path, const std::string& text) {
  const auto tmp = path.string() + ".tmp";
  {
    auto f = fmt::output_file(tmp);
    f.print("{}", text);
  }
  std::filesystem::rename(tmp, path);
}

// What the walls carry, averaged over 0.01 s more: a settled bed still rings, and one step's
// force swings by a few percent about the mean. The side walls' friction may hold the grains up
// or pull them down (after the bed's rebound), so the floor can carry more than the weight.
void report_wall_forces(Simulation& sim) {
  const auto steps = std::max<std::uint64_t>(
      1, static_cast<std::uint64_t>(std::llround(0.01 / sim.config().timestep)));
  double floor = 0.0, sides = 0.0; // upward force on the grains, N
  for (std::uint64_t k = 0; k < steps; ++k) {
    sim.step();
    const auto& walls = sim.world().walls;
    floor -= walls[0].force.y;
    for (std::size_t w = 1; w < walls.size(); ++w) sides -= walls[w].force.y;
  }
  floor /= static_cast<double>(steps), sides /= static_cast<double>(steps);
  double weight = 0.0;
  for (const double m : sim.world().particles.mass) weight += m * norm(sim.world().gravity);
  fmt::print("the walls carry {:.4f} N against the grains' weight {:.4f} N (mean over 0.01 s): "
             "the floor {:.4f} N, the side walls {:.4f} N ({})\n",
             floor + sides, weight, floor, sides,
             sides >= 0.0 ? "friction holding the grains up" : "friction pulling the grains down");
}

// particles.csv: every particle's final state, one row each
std::string final_state_csv(const Particles& p) {
  std::string csv = "id,x,y,angle,vx,vy,omega,radius,mass,kind\n";
  for (std::size_t i = 0; i < p.size(); ++i)
    csv +=
        fmt::format("{},{:.9e},{:.9e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{}\n", p.id[i],
                    p.position[i].x, p.position[i].y, p.angle[i], p.velocity[i].x, p.velocity[i].y,
                    p.angular_velocity[i], p.radius[i], p.mass[i], static_cast<int>(p.kind[i]));
  return csv;
}

void run_demo(const DemoOptions& o) {
  PourBoxSpec spec;
  spec.count = o.count;
  spec.seed = o.seed;
  PourBox box = build_pour_box(spec);
  box.config.integrator = parse_integrator(o.integrator);
  box.config.threads = o.threads;
  require(o.duration > 0.0, "--duration must be > 0 s");
  Simulation sim(std::move(box.world), box.config);

  const std::filesystem::path dir(o.out);
  if (std::filesystem::exists(dir / "thermo.csv"))
    fmt::print("talus demo: replacing the earlier demo in {} (--out DIR keeps it)\n", dir.string());
  std::filesystem::create_directories(dir);
  const auto steps = static_cast<std::uint64_t>(std::ceil(o.duration / box.config.timestep));
  const std::uint64_t every = std::max<std::uint64_t>(1, steps / 200);
  const std::uint64_t records_per_line =
      std::max<std::uint64_t>(1, 200 / static_cast<std::uint64_t>(o.lines));
  std::uint64_t records = 0;

  const Particles& p = sim.world().particles;
  double mean_weight_height = 0.0; // scale for the settled test: N m g R
  for (std::size_t i = 0; i < p.size(); ++i)
    mean_weight_height += p.mass[i] * std::abs(sim.world().gravity.y) * p.radius[i];

  fmt::print("talus demo: {} grains (R = {:.1f} mm +- {:.0f}%) poured into a box {:.3f} m wide\n",
             p.size(), spec.mean_radius * 1e3, spec.radius_spread * 100, box.box_width);
  fmt::print(
      "  integrator {}, normal law {}, tangential law {}, dt = {:.3e} s, {} steps, {} threads\n",
      to_string(sim.config().integrator), name_of(sim.config().normal_law),
      name_of(sim.config().tangential_law), sim.config().timestep, steps, sim.threads());
  fmt::print("{:>9} {:>12} {:>12} {:>12} {:>12} {:>7} {:>7}\n", "t [s]", "E_kin [J]", "E_el [J]",
             "E_grav [J]", "E_tot [J]", "Z", "phi");

  std::string thermo =
      "time,kinetic_translational,kinetic_rotational,elastic,gravitational,total,momentum_x,"
      "momentum_y,angular_momentum,coordination,packing_fraction,floor_force_y\n";
  const Vec2 region_lo{0.0, 0.0};
  const Vec2 region_hi{box.box_width, 10.0 * spec.mean_radius};
  bool settled = false;
  const auto start = std::chrono::steady_clock::now();
  auto record = [&](const Simulation& s) {
    const Energies e = energies(s);
    const Vec2 m = linear_momentum(s);
    const double z = coordination_number(s);
    const double phi = packing_fraction(s, region_lo, region_hi);
    thermo += fmt::format(
        "{:.6e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.6e},{:.6e},{:.6e},{:.4f},{:.4f},{:.6e}\n",
        s.time(), e.translational, e.rotational, e.elastic, e.gravitational, e.total(), m.x, m.y,
        angular_momentum(s), z, phi, s.world().walls[0].force.y);
    if (records++ % records_per_line == 0)
      fmt::print("{:9.4f} {:12.5e} {:12.5e} {:12.5e} {:12.5e} {:7.3f} {:7.3f}\n", s.time(),
                 e.kinetic(), e.elastic, e.gravitational, e.total(), z, phi);
    settled = s.time() > 0.2 && e.kinetic() < o.settle_ratio * mean_weight_height;
  };
  std::uint64_t done = 0;
  while (done < steps && !settled) {
    const std::uint64_t chunk = std::min(every, steps - done);
    sim.run(chunk);
    done += chunk;
    record(sim);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  write_atomically(dir / "thermo.csv", thermo);
  write_atomically(dir / "particles.csv", final_state_csv(p));
  write_snapshot_png(sim, (dir / "final.png").string(), 1200, SnapshotColour::size);
  const double rate = static_cast<double>(done) * static_cast<double>(p.size()) / seconds;
  fmt::print("{} after {} steps (t = {:.3f} s): {:.2f} s wall, {:.3e} particle-steps/s, "
             "{} neighbour-list builds\n",
             settled ? "settled" : "stopped at the duration", done, sim.time(), seconds, rate,
             sim.neighbours().builds);
  report_wall_forces(sim);
  fmt::print("wrote {0}/thermo.csv, {0}/particles.csv and {0}/final.png\n", dir.string());
}

} // namespace

void add_demo_command(CLI::App& app) {
  auto opts = std::make_shared<DemoOptions>();
  CLI::App* cmd = app.add_subcommand(
      "demo", "pour polydisperse grains into a box and let them settle under gravity");
  cmd->add_option("--n", opts->count, "number of grains")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--duration", opts->duration, "simulated time limit, s")->capture_default_str();
  cmd->add_option("--out", opts->out, "run folder (created)")->capture_default_str();
  cmd->add_option("--threads", opts->threads, "threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--integrator", opts->integrator, "gear or verlet")
      ->capture_default_str()
      ->check(CLI::IsMember({"gear", "verlet"}));
  cmd->add_option("--seed", opts->seed, "random seed of the grain sizes and positions")
      ->capture_default_str();
  cmd->add_option("--settle", opts->settle_ratio, "stop when kinetic energy < this x sum(m g R)")
      ->capture_default_str();
  cmd->callback([opts] { run_demo(*opts); });
}

} // namespace talus::cli
