#pragma once
// The structure of a 3D packing: the solid fraction of a box and the load-bearing network, as
// analysis/observables.hpp and analysis/rattlers.hpp give them in 2D. A sphere with fewer contacts
// than it needs to be held (d + 1 = 4 without friction, d = 3 with it; O'Hern et al. 2003) is a
// rattler; rattlers are taken out one by one until every sphere left has enough.
#include <cstddef>
#include <vector>

#include "analysis/rattlers.hpp"
#include "core/vec3.hpp"
#include "engine3d/simulation3.hpp"

namespace talus {

/// The volume of the intersection of the sphere (centre c, radius r) with the box [lo, hi], m^3:
/// the disks of its slices across z cut by the box's rectangle, integrated by Gauss-Legendre
/// between the heights where a slice's circle meets an edge or a corner of the rectangle (the
/// area is smooth between them). Exact for a sphere wholly inside or outside.
double sphere_box_volume(Vec3 c, double r, Vec3 lo, Vec3 hi);

/// The fraction of the box [lo, hi] the free spheres fill; in a periodic domain a sphere as it is
/// wrapped and its images, so the parts past the domain's sides count through them.
double packing_fraction(const Simulation3& sim, Vec3 lo, Vec3 hi);

/// The contacts a sphere needs to be held in the run's model: 4 without friction (the tangential
/// law `none` or every material with friction 0), else 3.
int contacts_needed(const Simulation3& sim);

/// The load-bearing network of the free spheres, with the statistics of those with their
/// centres in [lo, hi) (LoadBearing's grains are spheres here). A contact with a plate or a
/// fixed sphere holds as one that never leaves.
LoadBearing load_bearing(const Simulation3& sim, Vec3 lo, Vec3 hi, int needed);

} // namespace talus
