#pragma once
// The report page's tables of the run: the scenario as a paper's methods section states it, and
// run.json's figures with their units.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scenario/scenario.hpp"

namespace talus::cli {

using Rows = std::vector<std::pair<std::string, std::string>>;

/// Laws, integrator and timestep, container, grains (count, shape, sizes) and every material's
/// keys with their units.
Rows scenario_rows(const Scenario& s);
/// run.json's entries, each with its unit and in words.
Rows run_rows(const nlohmann::json& run);

} // namespace talus::cli
