#pragma once
// The built-in demo: polydisperse grains poured into an open box from a loose lattice.
#include <cstdint>

#include "simulation/simulation.hpp"

namespace talus {

struct PourBoxSpec {
  std::size_t count = 2000;    ///< number of grains
  double mean_radius = 5.0e-3; ///< m
  double radius_spread = 0.2;  ///< radii uniform in mean (1 +- spread)
  double box_width = 0.0;      ///< m; 0: about sqrt(count) * 1.6 mean diameters
  std::uint64_t seed = 1;
  Shape shape = Shape::sphere; ///< spheres moving in the plane
  double gravity = 9.81;       ///< m/s^2, downwards
};

struct PourBox {
  World world;
  SimulationConfig config; ///< timestep = collision time of the lightest pair / 50
  double box_width = 0.0;
};

/// Builds the box (floor and two side walls as segments), the grains on a jittered lattice above
/// the floor, and a linear spring-dashpot material with Cundall-Strack friction.
PourBox build_pour_box(const PourBoxSpec& spec);

} // namespace talus
