#pragma once
// The scenarios shipped in inputs/*/scenario.toml, compiled into the program.
#include <string>
#include <string_view>
#include <vector>

namespace talus::cli {

struct BuiltinScenario {
  std::string_view name;
  std::string_view text; ///< the TOML file
};

const std::vector<BuiltinScenario>& builtin_scenarios();

} // namespace talus::cli
