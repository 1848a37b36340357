#pragma once
// Everything that is simulated: particles, walls, materials, the box, gravity and drivers.
#include <vector>

#include "core/domain.hpp"
#include "drivers/drivers.hpp"
#include "materials/material.hpp"
#include "state/particles.hpp"
#include "state/walls.hpp"

namespace talus {

struct World {
  Particles particles;
  Segments walls;
  std::vector<Material> materials{Material{}};
  Domain domain;
  Vec2 gravity{0.0, 0.0}; ///< m/s^2
  std::vector<Driver> drivers;
  double disk_thickness = 1.0; ///< m: disks have mass rho pi r^2 thickness

  /// Adds a particle; mass and inertia from the shape and the material's density unless given.
  std::size_t add_particle(ParticleSpec spec);
  /// Adds a segment wall from a to b. Returns its index.
  std::size_t add_wall(Vec2 a, Vec2 b, std::uint16_t material = 0);
  /// Adds a material. Returns its index.
  std::uint16_t add_material(const Material& m);
};

} // namespace talus
