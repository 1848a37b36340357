#pragma once
// The talus subcommands. Each registers its options on the CLI11 app and runs when chosen.
#include <CLI/CLI.hpp>

namespace talus::cli {

/// `talus demo`: grains poured into a box settle under gravity (the README's main job).
void add_demo_command(CLI::App& app);

} // namespace talus::cli
