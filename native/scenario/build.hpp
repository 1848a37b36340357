#pragma once
// Scenario -> a World ready to run: container, grains placed (and settled), drivers, timestep.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "scenario/scenario.hpp"
#include "simulation/simulation.hpp"

namespace talus {

struct BuiltScenario {
  World world;
  SimulationConfig config;
  std::map<std::string, DriverTargets> groups; ///< wall groups of the container
  std::vector<std::uint32_t> tracked;          ///< indices of tracked particles
  Rect fill;                                   ///< the region grains were placed in
  Rect bounds;                                 ///< the container's extent
  double collision_time = 0.0;                 ///< s, of the stiffest pair
  double settle_time = 0.0;                    ///< s of sedimentation (0 if none)
  bool settled = true;
};

/// Progress of sedimentation: simulated time and kinetic energy (J).
using SettleProgress = std::function<void(double time, double kinetic_energy)>;

/// Builds everything. Throws ScenarioError naming the key for anything that cannot be built
/// (too many grains for the region, a timestep above the stability bound, an unknown group).
BuiltScenario build_scenario(const Scenario& s, const SettleProgress& progress = {});

/// Shortest collision time of a grain pair of the smallest size, for each material pair used.
double shortest_collision_time(const Scenario& s, const std::vector<Material>& materials,
                               double r_min);

} // namespace talus
