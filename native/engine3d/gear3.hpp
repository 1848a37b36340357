#pragma once
// The thesis' 5-value Gear predictor-corrector (the 2D engine's: integrate/integrator.hpp, its
// corrector weights gear_c) for spheres in 3D: each free sphere's position with its velocity and
// next three derivatives, and its spin with its next three. A sphere's orientation is not
// tracked: no law here depends on it.
#include <vector>

#include "engine3d/spheres.hpp"

namespace talus {

struct GearState3 {
  std::vector<Vec3> r2, r3, r4; ///< a sphere's acceleration and its next two derivatives
  std::vector<Vec3> w2, w3, w4; ///< its spin's first three derivatives
};

/// Starts the derivatives from the current forces: r2 = F/m, w2 = T/I, the higher ones 0.
void gear_initialise(GearState3& g, const Spheres& s);

/// Moves every free sphere's values dt ahead along their Taylor series (the predictor).
/// `rotation` false (a step without rotation) leaves the spins and their derivatives as they are.
void gear_predict(GearState3& g, Spheres& s, double dt, int threads, bool rotation = true);

/// Corrects every free sphere's values from the forces at the predicted state (the corrector):
/// each value k moves by gear_c[k] k!/dt^k (dt^2/2) (F/m - r2), and likewise for the spin.
void gear_correct(GearState3& g, Spheres& s, double dt, int threads, bool rotation = true);

} // namespace talus
