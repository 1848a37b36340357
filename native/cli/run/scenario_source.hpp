#pragma once
// Where a command's scenario comes from: a .toml file, a thesis .in file or a built-in name.
#include <string>
#include <vector>

#include "scenario/scenario.hpp"

namespace talus::cli {

/// The scenario `what` names, with the --set overrides applied. Throws InvalidArgument listing the
/// built-in names (and the nearest one) for a name that is neither a file nor built in.
Scenario resolve_scenario(const std::string& what, const std::vector<std::string>& overrides);

} // namespace talus::cli
