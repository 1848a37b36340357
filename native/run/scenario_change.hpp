#pragma once
// What a change of the scenario during a run (a stage's start, talus resume --set) does to the
// engine: the keys that may change (scenario/stages.hpp) that the engine holds.
#include "scenario/scenario.hpp"
#include "simulation/simulation.hpp"

namespace talus::run {

/// Applies to `sim` what differs from `before` in `after`: gravity, the materials' contact keys,
/// the tangential law. The output intervals are the run's own. Throws ScenarioError for any
/// other difference (a key that cannot change during a run).
void apply_scenario_change(Simulation& sim, const Scenario& before, const Scenario& after);

} // namespace talus::run
