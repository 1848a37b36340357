#pragma once
// What a change of the scenario during a run (a stage's start, talus resume --set) does to the
// engine: the keys that may change (scenario/stages.hpp) that the engine holds.
#include <cstdint>
#include <vector>

#include "run/run_book.hpp"
#include "scenario/scenario.hpp"
#include "simulation/simulation.hpp"

namespace talus::run {

/// Applies to `sim` what differs from `before` in `after`: gravity, the materials' contact keys,
/// the tangential law, drivers' motions, the timestep (the one `after` asks for, if it is not the
/// one in force: a given one, or the collision time of the materials now over the factor) and the
/// walls of geometry.gate and geometry.segments (the book's wall groups follow; stages from
/// book.stage on are checked against them). The output intervals are the run's own. Throws
/// ScenarioError for any other difference (a key that cannot change during a run) and for a
/// change that cannot be made, before anything is changed. Returns each old wall's new index
/// (-1: removed), or nothing when no wall changed.
std::vector<std::int64_t> apply_scenario_change(Simulation& sim, const Scenario& before,
                                                const Scenario& after, RunBook& book);

} // namespace talus::run
