#pragma once
// A test's run of a scenario, and its resume, quietly, as `talus run` and `talus resume` do them.
#include <filesystem>

#include "cli/run/run_loop.hpp"

namespace talus::testing {

inline int run_quietly(const Scenario& s, const std::filesystem::path& dir, double stop_at = -1.0) {
  cli::RunOptions o;
  o.quiet = true;
  o.stop_at = stop_at;
  return cli::start_run(s, build_scenario(s), dir.string(), o);
}

inline int resume_quietly(const std::filesystem::path& dir) {
  cli::RunOptions o;
  o.quiet = true;
  return cli::resume_run(dir.string(), o);
}

} // namespace talus::testing
