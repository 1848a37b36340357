#pragma once
// `talus run` of a 3D scenario (simulation.dimension = 3): the spheres poured in a run folder,
// with thermo.csv, ParaView snapshots, checkpoints and run.json (run3d_session.hpp).
#include <filesystem>
#include <string>

#include "cli/run/run_loop.hpp"
#include "scenario3d/scenario3.hpp"

namespace talus::cli {

/// Runs `s` in a new run folder `dir` (as RunFolder::create allows); `source` (the scenario as
/// the user named it) prefixes a scenario error, after which nothing is left behind. Returns the
/// exit status (exit_interrupted after SIGINT or SIGTERM, exit_stopped at --stop-at, each after
/// a checkpoint that talus resume continues).
int run_3d(const Scenario3& s, const std::string& dir, const RunOptions& o,
           const std::string& source);

/// Whether `dir` holds a run of spheres in 3D (its scenario.toml says simulation.dimension = 3).
bool is_3d_run_folder(const std::filesystem::path& dir);
/// Throws InvalidArgument when `dir` holds a run of spheres in 3D (its scenario.toml says
/// simulation.dimension = 3): `command` takes 2D runs for now, and says so before it reads a file.
void refuse_3d_run_folder(const std::filesystem::path& dir, const std::string& command);

} // namespace talus::cli
