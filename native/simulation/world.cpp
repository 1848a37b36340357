#include "simulation/world.hpp"

#include <limits>
#include <string>

#include "talus/error.hpp"

namespace talus {

std::size_t World::add_particle(ParticleSpec spec) {
  require(spec.material < materials.size(),
          "particle material index " + std::to_string(spec.material) + " out of range; " +
              std::to_string(materials.size()) + " material(s) defined");
  require(spec.radius > 0.0, "particle radius must be > 0 m");
  if (spec.mass <= 0.0)
    spec.mass =
        shape_mass(spec.shape, spec.radius, materials[spec.material].density, disk_thickness);
  if (spec.inertia <= 0.0) spec.inertia = shape_inertia(spec.shape, spec.mass, spec.radius);
  return particles.add(spec);
}

std::size_t World::add_wall(Vec2 a, Vec2 b, std::uint16_t material) {
  require(material < materials.size(), "wall material index out of range");
  require(a != b, "a segment wall needs two distinct end points");
  Segment s;
  s.a = a;
  s.b = b;
  s.material = material;
  walls.push_back(s);
  return walls.size() - 1;
}

std::uint16_t World::add_material(const Material& m) {
  validate(m);
  require(materials.size() < std::numeric_limits<std::uint16_t>::max(), "too many materials");
  materials.push_back(m);
  return static_cast<std::uint16_t>(materials.size() - 1);
}

} // namespace talus
