#pragma once
// A 3D scenario built: spheres on a loose lattice in a box of plates, ready to pour.
#include "engine3d/simulation3.hpp"
#include "scenario3d/scenario3.hpp"

namespace talus {

struct BuiltScenario3 {
  Scene3 scene;
  Settings3 settings;
  double collision_time = 0.0; ///< s: the shortest of the pairs that can meet
};

/// The spheres' radii drawn from particles.size (seeded by simulation.seed), the spheres put at
/// rest on a cubic lattice of spacing 2.2 R_max from the floor up, each nudged by up to 5% of
/// the spacing, in the box, whose sides that do not wrap are plates. The timestep is the
/// shortest collision time / timestep_factor, or the one given if it is at most the collision
/// time / 5. Throws ScenarioError naming the key when the spheres do not fit the box or the
/// timestep is too long.
BuiltScenario3 build_scenario3(const Scenario3& s);

} // namespace talus
