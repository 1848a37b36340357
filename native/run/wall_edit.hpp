#pragma once
// Walls taken away or put up during a run: what a change of geometry.gate (an orifice opened
// by removing its gate, or closed) or of geometry.segments (extra walls) does to the world's
// walls and to the run's wall groups.
#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "scenario/scenario.hpp"
#include "simulation/simulation.hpp"

namespace talus::run {

/// The walls a change removes and adds, and the wall groups after it.
struct WallEdit {
  std::vector<bool> removed; ///< per wall of the world now
  Segments added;            ///< appended after the walls that stay
  /// Every group after the change, its walls in the geometry's order: an index >= 0 is a wall
  /// of the world now, -1 - k the k-th added wall. "walls", their union, is made from them.
  std::map<std::string, std::vector<std::int64_t>> groups;
  bool any() const {
    return !added.empty() || std::find(removed.begin(), removed.end(), true) != removed.end();
  }
};

/// The walls `after` has that `before` had not and the other way round, given the world `w` and
/// the run's wall groups (by name, the world's indices). Throws ScenarioError naming the key for
/// what cannot be: walls made of particles, a driven wall removed or a wall added to a driven
/// group, a group that a stage from `first_stage` on waits for removed, a wall added across a
/// grain.
WallEdit wall_edit(const Scenario& before, const Scenario& after, const World& w,
                   const std::map<std::string, DriverTargets>& groups, std::size_t first_stage);

/// Makes the edit in `sim` and in `groups`. Returns each old wall's new index (-1: removed).
std::vector<std::int64_t> apply_wall_edit(Simulation& sim, const WallEdit& e,
                                          std::map<std::string, DriverTargets>& groups);

} // namespace talus::run
