#pragma once
// What a scenario must satisfy to be built: checks that refuse it, with a ScenarioError naming the
// key and the allowed values, before anything is allocated or run.
#include <cstddef>
#include <string>

#include "scenario/scenario.hpp"
#include "simulation/world.hpp"

namespace talus {

/// The peak memory (bytes, resident) of a run of `particles` particles, the process included.
double memory_estimate(std::size_t particles);
/// "1.16 GB", "21.5 MB": bytes for a message.
std::string readable_bytes(double bytes);
/// Refuses what the machine, or this process' limits (ulimit -v, -d), cannot hold.
void check_memory(std::size_t particles);
/// Refuses a scene reaching so far from the origin that positions there cannot resolve a
/// millionth of the smallest radius.
void check_position_resolution(const Scenario& s, const Rect& bounds, const Rect& fill,
                               double r_min);
/// Refuses a run, or a settling, of more steps than any machine finishes (a stiffness that makes
/// the timestep vanishingly small, say).
void check_step_count(const Scenario& s, double timestep);
/// Refuses listed grains overlapping each other beyond 1% of the smaller radius.
void check_start_overlaps(const Scenario& s);
/// Refuses hand-made walls with a gap a grain can slip through.
void check_wall_gaps(const Scenario& s, double r_min, double r_max);
/// Refuses listed grains outside the container or overlapping its walls.
void check_listed_grains_clear_of_walls(const Scenario& s, const World& w, const Rect& bounds);

} // namespace talus
