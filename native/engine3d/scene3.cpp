#include "engine3d/scene3.hpp"

#include <string>

#include "talus/error.hpp"

namespace talus {

std::size_t Scene3::add_sphere(SphereSpec spec) {
  require(spec.material < materials.size(), "a sphere's material " + std::to_string(spec.material) +
                                                " is not defined; allowed: 0 to " +
                                                std::to_string(materials.size() - 1));
  if (spec.mass <= 0.0)
    spec.mass = shape_mass(Shape::sphere, spec.radius, materials[spec.material].density);
  if (spec.inertia <= 0.0) spec.inertia = shape_inertia(Shape::sphere, spec.mass, spec.radius);
  return spheres.add(spec);
}

} // namespace talus
