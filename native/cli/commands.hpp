#pragma once
// The talus subcommands. Each registers its options on the CLI11 app and runs when chosen.
#include <CLI/CLI.hpp>

namespace talus::cli {

/// Exit status of the chosen command (set by the command's callback).
int& exit_status();

/// `talus demo`: grains poured into a box settle under gravity (the README's main job).
void add_demo_command(CLI::App& app);
/// `talus run SCENARIO`: a scenario file, a thesis .in file or a built-in scenario's name.
void add_run_command(CLI::App& app);
/// `talus resume DIR`: continue a stopped run from its last checkpoint.
void add_resume_command(CLI::App& app);
/// `talus sweep SCENARIO --vary KEY=V1,V2 [--seeds N]`: a parameter sweep.
void add_sweep_command(CLI::App& app);
/// `talus scenarios`: the built-in scenarios, one line each.
void add_scenarios_command(CLI::App& app);
/// `talus convert IN OUT`: thesis .in <-> scenario .toml.
void add_convert_command(CLI::App& app);
/// `talus render DIR` and `talus movie DIR`: pictures and a movie of a run's snapshots.
void add_picture_commands(CLI::App& app);
/// `talus analyze DIR [WHAT]`: analyses with CSV and charts.
void add_analyze_command(CLI::App& app);
/// `talus checkpoint DIR`: what the last checkpoint holds, with a hash of the state.
void add_checkpoint_command(CLI::App& app);
/// `talus export lammps SCENARIO DIR`: a scenario as a LAMMPS case (pair_style granthesis).
void add_export_command(CLI::App& app);
/// `talus bench dense2d`: the reference benchmark, optionally beside LAMMPS.
void add_bench_command(CLI::App& app);

} // namespace talus::cli
