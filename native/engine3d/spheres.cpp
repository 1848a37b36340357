#include "engine3d/spheres.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "talus/error.hpp"

namespace talus {

double Spheres::max_radius() const {
  return radius.empty() ? 0.0 : *std::max_element(radius.begin(), radius.end());
}

std::size_t Spheres::add(const SphereSpec& s) {
  require(s.radius > 0.0 && std::isfinite(s.radius),
          "a sphere's radius must be finite and > 0 m, not " + std::to_string(s.radius));
  require(s.mass > 0.0 && s.inertia > 0.0, "a sphere's mass and inertia must be resolved (> 0)");
  require(s.kind != Kind::moved,
          "a sphere moved by a driver is not there yet in 3D; allowed kinds: free, fixed");
  const bool free = s.kind == Kind::free;
  position.push_back(s.position);
  velocity.push_back(free ? s.velocity : Vec3{});
  force.push_back({});
  angular_velocity.push_back(free ? s.angular_velocity : Vec3{});
  torque.push_back({});
  radius.push_back(s.radius);
  mass.push_back(s.mass);
  inertia.push_back(s.inertia);
  inv_mass.push_back(free ? 1.0 / s.mass : 0.0);
  inv_inertia.push_back(free ? 1.0 / s.inertia : 0.0);
  material.push_back(s.material);
  kind.push_back(s.kind);
  id.push_back(static_cast<std::uint32_t>(id.size()));
  image.push_back({});
  force_previous.push_back({});
  torque_previous.push_back({});
  return size() - 1;
}

} // namespace talus
