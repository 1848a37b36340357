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
  PairTable pairs; ///< the materials' pairs, mixed once: every bound and estimate reads them
  double collision_time = 0.0; ///< s, of the stiffest pair
  double settle_time = 0.0;    ///< s of sedimentation (0 if none)
  bool settled = true;
};

/// Progress of sedimentation: simulated time and kinetic energy (J).
using SettleProgress = std::function<void(double time, double kinetic_energy)>;

/// Builds everything. Throws ScenarioError naming the key for anything that cannot be built
/// (too many grains for the region, a timestep above the stability bound, an unknown group).
BuiltScenario build_scenario(const Scenario& s, const SettleProgress& progress = {});

/// The motion a driver section asks for.
Motion motion_of(const DriverSection& d);
/// The drivers of the built world, in its order: the geometry builder's (the grain press' lid,
/// the drum's turn), then the scenario's [[drivers]].
std::vector<DriverSection> all_drivers(const Scenario& s);

/// The scenario's materials as the engine takes them: a damping left to be derived from the
/// restitution that the normal law does not use (the linear law's Hertz A) set to zero; Hertz' A
/// stays to be derived per contact.
std::vector<Material> engine_materials(const Scenario& s);

/// Segment ends closer than this many smallest grain radii are one joint (join_segment_ends): far
/// below any gap a grain could notice, far above rounding.
inline constexpr double wall_joint_tolerance = 1e-6;

/// A pair of materials that can meet: two grains' (a <= b), or a grain's (a) and a wall's (b).
/// Two walls never meet, so their pair never sets the timestep.
struct MeetingPair {
  std::uint16_t a = 0, b = 0;
  bool wall = false;
};

/// The material pairs that can meet in w: free particles' materials with each other and with
/// those of the wall particles and segments.
std::vector<MeetingPair> meeting_pairs(const World& w);

/// Shortest collision time over the pairs of `pairs` (w's materials) that can meet, for grains of
/// the smallest size (against a wall, the grain's own mass and radius).
double shortest_collision_time(const Scenario& s, const World& w, const PairTable& pairs,
                               double r_min);

/// The timestep `s` asks for in `w` with the settings `c` (integrator, laws): simulation.timestep,
/// checked against the integrator's stability bound for the stiffest contact, or "auto", the
/// collision time (shortest_collision_time) / simulation.timestep_factor. Throws ScenarioError
/// naming the key and the bound.
double chosen_timestep(const Scenario& s, const World& w, const PairTable& pairs,
                       const SimulationConfig& c, double r_min, double collision_time);

} // namespace talus
