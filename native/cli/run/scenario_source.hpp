#pragma once
// Where a command's scenario comes from: a .toml file, a thesis .in file or a built-in name.
#include <cstdint>
#include <string>
#include <vector>

#include "scenario/scenario.hpp"

namespace talus::cli {

/// A scenario's TOML text and the name errors give its source by.
struct ScenarioText {
  std::string text;
  std::string file;
};

/// The text of the scenario `what` names (a thesis .in file converted). Throws InvalidArgument
/// listing the built-in names (and the nearest one) for a name that is neither a file nor built
/// in.
ScenarioText scenario_text(const std::string& what);
/// simulation.dimension of the text with the overrides applied: 2 or 3.
int scenario_dimension(const ScenarioText& t, const std::vector<std::string>& overrides);

/// The scenario `what` names, with the --set overrides applied.
Scenario resolve_scenario(const std::string& what, const std::vector<std::string>& overrides);

/// A scenario of either dimension resolved: every key with its value as TOML (it reruns as it
/// is), and what a sweep names its runs by.
struct ResolvedScenario {
  std::string toml;
  std::string name;
  std::uint64_t seed = 0;
  int dimension = 2;
};
/// The scenario `what` names with the overrides, checked by the loader of its dimension.
ResolvedScenario resolve_any_scenario(const std::string& what,
                                      const std::vector<std::string>& overrides);

} // namespace talus::cli
