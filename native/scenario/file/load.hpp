#pragma once
// Scenario files: TOML text -> Scenario (checked, defaults filled), and Scenario -> TOML.
#include <string>
#include <string_view>
#include <vector>

#include "scenario/file/toml_reader.hpp"
#include "scenario/scenario.hpp"

namespace talus {

/// Parses and checks a scenario. `file` names the source in error messages. `overrides` are
/// "dotted.key=value" strings applied before checking (value in TOML syntax; a bare word is taken
/// as a string), e.g. "particles.count=5000" or "materials.0.friction=0.3".
Scenario load_scenario(std::string_view text, const std::string& file,
                       const std::vector<std::string>& overrides = {});
/// Reads the file at path and loads it.
Scenario load_scenario_file(const std::string& path,
                            const std::vector<std::string>& overrides = {});

/// TOML text with each float written as the shortest text that reads back to the same double.
std::string with_shortest_floats(const std::string& toml_text);

/// The resolved scenario as TOML: every key with its value, so it reruns the same run.
std::string to_toml(const Scenario& s);

/// Index of the material named `name`; throws ScenarioError listing the names otherwise.
std::uint16_t material_index(const Scenario& s, const std::string& name, const std::string& key);

} // namespace talus
