#pragma once
// Scenario files of spheres in 3D (simulation.dimension = 3): TOML -> Scenario3 (checked,
// defaults filled) and back.
#include <string>
#include <string_view>
#include <vector>

#include "scenario/file/toml_reader.hpp"
#include "scenario3d/scenario3.hpp"

namespace talus {

/// Parses and checks a 3D scenario, `overrides` applied first (as load_scenario's). Sections and
/// keys the 3D engine does not have yet are refused, naming them.
Scenario3 load_scenario3(std::string_view text, const std::string& file,
                         const std::vector<std::string>& overrides = {});
/// The resolved 3D scenario as TOML: every key with its value, so it reruns the same run.
std::string to_toml(const Scenario3& s);
/// Index of the material named `name` (0 for ""); throws ScenarioError listing the names.
std::uint16_t material_index(const Scenario3& s, const std::string& name, const std::string& key);

} // namespace talus
