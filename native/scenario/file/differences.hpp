#pragma once
// Where two scenarios differ, key by key: how an edit of a run folder's scenario.toml becomes
// changes from the resume point, as `talus resume --set` makes them.
#include <optional>
#include <string>
#include <vector>

#include "scenario/scenario.hpp"

namespace talus {

struct KeyDifference {
  std::string key;                  ///< dotted, tables of arrays by index: "materials.0.friction"
  std::optional<std::string> value; ///< its value in the second scenario, as TOML writes it;
                                    ///< empty when only the first has the key
};

/// The keys of the resolved scenarios (to_toml) whose values differ, in the first's order, then
/// those only the second has.
std::vector<KeyDifference> scenario_differences(const Scenario& a, const Scenario& b);

} // namespace talus
