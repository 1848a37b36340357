#pragma once
// A built-in scenario (native/cli/builtin_scenarios.hpp) loaded with --set style overrides.
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/builtin_scenarios.hpp"
#include "scenario/file/load.hpp"

namespace talus::testing {

inline Scenario builtin(const std::string& name, const std::vector<std::string>& set) {
  for (const auto& b : cli::builtin_scenarios())
    if (b.name == name) return load_scenario(b.text, name, set);
  throw std::runtime_error("no built-in " + name);
}

} // namespace talus::testing
