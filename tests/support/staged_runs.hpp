#pragma once
// Runs started and resumed as `talus run` and `talus resume` do, quietly, into a folder, and
// what the tests of runs changed as they go read back from it.
#include <filesystem>
#include <string>
#include <vector>

#include "cli/run/run_loop.hpp"
#include "io/checkpoint.hpp"
#include "scenario/build.hpp"
#include "support/run_scenario.hpp"

namespace talus::testing {

inline std::string file(const std::filesystem::path& p) {
  return read_file(p.string());
}

/// The engine's state at the folder's last checkpoint, every byte of it.
inline std::string final_state(const std::filesystem::path& dir) {
  const Checkpoint c = decode_checkpoint(file(dir / "checkpoint.bin"), "x");
  return encode_checkpoint({c.state, c.config, ""});
}

/// talus run into `dir`, stopping at `stop_at` s (-1: the end). Returns the exit code.
inline int start(const Scenario& s, const std::filesystem::path& dir, double stop_at = -1.0) {
  return run_quietly(s, dir, stop_at);
}

/// talus resume DIR [--stop-at] [--set ...] [--duration]. Returns the exit code.
inline int resume(const std::filesystem::path& dir, double stop_at = -1.0,
                  std::vector<std::string> set = {}, double duration = -1.0) {
  cli::RunOptions o;
  o.quiet = true;
  o.stop_at = stop_at;
  o.set = std::move(set);
  o.duration = duration;
  return cli::resume_run(dir.string(), o);
}

} // namespace talus::testing
