#pragma once
// A scenario's stages ([[stages]], StageSection): reading them, and which keys a stage (or
// `talus resume --set`) may change while a run goes on.
#include <string>
#include <vector>

#include "scenario/file/toml_reader.hpp"
#include "scenario/scenario.hpp"

namespace talus {

/// The stages of the table `top` ([[stages]]), each read and checked on its own: a duration
/// (> 0 s; the last may leave it out when simulation.duration is given), a condition and its
/// threshold, and the `set` table's keys as "key=value" changes (a first stage may not have
/// them: its settings are the scenario's own).
std::vector<StageSection> read_stages(TableReader& top, const std::string& file);

/// Whether `key` ("simulation.gravity", "materials.0.friction") may change during a run: gravity,
/// the tangential law, the timestep, the gate and the extra walls (segment walls added or
/// removed), a driver's motion, a material's contact keys (not its density: the grains' masses
/// are made) and the output intervals.
bool changeable_during_run(const std::string& key);
/// The keys that may change during a run, in words, for error messages.
std::string changeable_keys_text();

/// The key of a "key=value" change (materials[0].friction reads materials.0.friction).
std::string change_key(const std::string& change);

} // namespace talus
