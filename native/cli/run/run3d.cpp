#include "cli/run/run3d.hpp"

#include <chrono>
#include <fstream>

#include <fmt/core.h>
#include <fmt/format.h>
#include <toml++/toml.h>

#include "io/checkpoint.hpp"
#include "io/vtk.hpp"
#include "io/vtk_spheres.hpp"
#include "run/progress.hpp"
#include "run/records.hpp"
#include "scenario/build3.hpp"
#include "scenario/file/load3.hpp"

namespace talus::cli {

namespace {

constexpr const char* thermo_header =
    "time,step,kinetic,rotational,potential,elastic,total,contacts,coordination,list_builds\n";

std::string thermo_row(const Simulation3& sim) {
  const Energies3 e = sim.energies();
  return fmt::format("{:.9g},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{},{:.6g},{}\n", sim.time(),
                     sim.step_count(), e.kinetic, e.rotational, e.potential, e.elastic, e.total(),
                     sim.contact_count(), sim.coordination(), sim.list().builds);
}

// The snapshots so far and their collection: spheres and plates, one file each per snapshot.
struct Snapshots3 {
  std::filesystem::path dir;
  double reach = 0.0; ///< m: how far a whole plane is drawn from its centre
  std::vector<std::pair<double, std::string>> spheres, plates;

  void write(const Simulation3& sim) {
    const std::string k = fmt::format("{:06d}", spheres.size());
    const std::string s = "snapshots/spheres_" + k + ".vtp", p = "snapshots/plates_" + k + ".vtp";
    write_file_atomically((dir / s).string(), vtp_spheres(sim.scene()));
    write_file_atomically((dir / p).string(), vtp_plates(sim.scene(), reach));
    spheres.emplace_back(sim.time(), s);
    plates.emplace_back(sim.time(), p);
    write_file_atomically((dir / "particles.pvd").string(), pvd_collection(spheres));
    write_file_atomically((dir / "walls.pvd").string(), pvd_collection(plates));
  }
};

std::string run_json(const Scenario3& s, const Simulation3& sim, const BuiltScenario3& b,
                     double wall, const std::string& ended) {
  const std::size_t n = sim.scene().spheres.size();
  const double rate = wall > 0 ? static_cast<double>(sim.step_count() * n) / wall : 0.0;
  return fmt::format(
      "{{\n  \"talus_version\": \"{}\",\n  \"scenario\": \"{}\",\n  \"dimension\": 3,\n"
      "  \"seed\": {},\n  \"particles\": {},\n  \"plates\": {},\n  \"steps\": {},\n"
      "  \"time\": {:.9g},\n  \"timestep\": {:.9g},\n  \"collision_time\": {:.9g},\n"
      "  \"integrator\": \"verlet\",\n  \"threads\": {},\n  \"wall_seconds\": {:.6f},\n"
      "  \"particle_steps_per_second\": {:.6g},\n  \"ended_by\": \"{}\"\n}}\n",
      TALUS_VERSION, s.name, s.simulation.seed, n, sim.scene().plates.size(), sim.step_count(),
      sim.time(), sim.settings().timestep, b.collision_time, sim.threads(), wall, rate, ended);
}

BuiltScenario3 build_or_discard(const Scenario3& s, RunFolder& folder, const std::string& source) {
  try {
    return build_scenario3(s);
  } catch (const ScenarioError& e) { // say which file the key is in; leave nothing behind
    folder.discard();
    throw ScenarioError(source + ": " + e.what());
  } catch (...) {
    folder.discard();
    throw;
  }
}

} // namespace

void refuse_3d_run_folder(const std::filesystem::path& dir, const std::string& command) {
  const std::filesystem::path file = dir / "scenario.toml";
  if (!std::filesystem::is_regular_file(file)) return;
  try {
    const toml::table t = toml::parse_file(file.string());
    if (t["simulation"]["dimension"].value_or(std::int64_t{2}) != 3) return;
  } catch (const toml::parse_error&) {
    return; // the command itself says what is wrong with the file
  }
  throw InvalidArgument("talus " + command + ": '" + dir.string() +
                        "' is a run of spheres in 3D; talus " + command +
                        " takes 2D runs for now (docs/scenarios.md, \"Spheres in 3D\"): open " +
                        (dir / "particles.pvd").string() + " in ParaView");
}

int run_3d(const Scenario3& s, const std::string& dir, const RunOptions& o,
           const std::string& source) {
  if (o.stop_at >= 0.0)
    throw InvalidArgument("--stop-at: a 3D run cannot be stopped and resumed yet (no checkpoints "
                          "in 3D); run it to its end, or shorten simulation.duration");
  RunFolder folder = RunFolder::create(dir, to_toml(s));
  catch_stop_signals();
  BuiltScenario3 built = build_or_discard(s, folder, source);
  const std::size_t n = built.scene.spheres.size(), plates = built.scene.plates.size();
  if (o.threads >= 0) built.settings.threads = o.threads;
  Simulation3 sim = [&] {
    try {
      return Simulation3(built.scene, built.settings);
    } catch (...) { // nothing left behind
      folder.discard();
      throw;
    }
  }();
  if (!o.quiet) {
    fmt::print("talus run {}: {}\n", s.name,
               s.description.empty() ? "(no description)" : s.description);
    fmt::print("  {} spheres, {} plates (3D); dt = {:.4g} s (collision time {:.4g} s); {} "
               "thread(s)\n",
               n, plates, built.settings.timestep, built.collision_time, sim.threads());
  }
  Snapshots3 snapshots{folder.path(), norm(s.geometry.hi - s.geometry.lo), {}, {}};
  const double dt = built.settings.timestep;
  const std::uint64_t total = steps_until(s.simulation.duration, dt);
  const auto every = [&](double interval) {
    return interval > 0.0 ? std::max<std::uint64_t>(1, steps_until(interval, dt)) : 0;
  };
  const std::uint64_t thermo_every = every(s.output.thermo_interval),
                      snapshot_every = every(s.output.snapshot_interval);
  std::ofstream thermo(folder.path() / "thermo.csv");
  thermo << thermo_header << thermo_row(sim);
  if (snapshot_every > 0) snapshots.write(sim);
  run::RunProgress progress(o.quiet, s.simulation.duration, s.output.thermo_interval, dt);
  const auto start = std::chrono::steady_clock::now();
  const auto wall = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  std::string ended = "duration";
  while (sim.step_count() < total) {
    if (stop_signal()) {
      ended = "signal";
      break;
    }
    try {
      sim.step();
    } catch (const InstabilityError&) { // the outputs up to the last good step stay
      thermo.close();
      write_file_atomically((folder.path() / "run.json").string(),
                            run_json(s, sim, built, wall(), "unstable"));
      throw;
    }
    const std::uint64_t k = sim.step_count();
    if (k % thermo_every == 0 || k == total) thermo << thermo_row(sim) << std::flush;
    if (snapshot_every > 0 && (k % snapshot_every == 0 || k == total)) snapshots.write(sim);
    if (k % 256 == 0 || k == total)
      progress.report(sim.time(), k, total, total, wall(), k, sim.energies().kinetic);
  }
  progress.finish();
  thermo.close();
  write_file_atomically((folder.path() / "run.json").string(),
                        run_json(s, sim, built, wall(), ended));
  if (ended == "signal") {
    fmt::print(stderr,
               "talus: interrupted at t = {:.6g} s; its outputs are in {} (a 3D run "
               "cannot be resumed yet)\n",
               sim.time(), folder.path().string());
    return exit_interrupted;
  }
  if (!o.quiet)
    fmt::print("finished at t = {:.6g} s after {} steps; run folder {}\n", sim.time(),
               sim.step_count(), folder.path().string());
  return exit_completed;
}

} // namespace talus::cli
