#include "cli/run/run3d.hpp"

#include <fmt/core.h>
#include <fmt/format.h>
#include <toml++/toml.h>

#include "cli/run/run3d_session.hpp"
#include "scenario/file/load3.hpp"
#include "scenario3d/build3.hpp"

namespace talus::cli {

namespace {

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

bool is_3d_run_folder(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / "scenario.toml";
  if (!std::filesystem::is_regular_file(file)) return false;
  try {
    const toml::table t = toml::parse_file(file.string());
    return t["simulation"]["dimension"].value_or(std::int64_t{2}) == 3;
  } catch (const toml::parse_error&) {
    return false; // the command itself says what is wrong with the file
  }
}

void refuse_3d_run_folder(const std::filesystem::path& dir, const std::string& command) {
  if (!is_3d_run_folder(dir)) return;
  throw InvalidArgument("talus " + command + ": '" + dir.string() +
                        "' is a run of spheres in 3D; talus " + command +
                        " takes 2D runs for now (docs/scenarios.md, \"Spheres in 3D\"): open " +
                        (dir / "particles.pvd").string() + " in ParaView");
}

int run_3d(const Scenario3& s, const std::string& dir, const RunOptions& o,
           const std::string& source) {
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
    fmt::print("  step: {}\n", sim.step_description() == "general"
                                   ? "the general one (the scene uses every feature it has)"
                                   : "specialised to the scene: " + sim.step_description());
  }
  Book3 book;
  book.collision_time = built.collision_time;
  return run_session3(s, sim, book, folder, o);
}

} // namespace talus::cli
