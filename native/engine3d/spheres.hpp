#pragma once
// Spheres in 3D as a structure of arrays: one vector per field, indexed by sphere.
#include <cstdint>
#include <vector>

#include "engine3d/domain3.hpp"
#include "state/particles.hpp"

namespace talus {

/// What it takes to add one sphere.
struct SphereSpec {
  Vec3 position;
  double radius = 0.0;
  std::uint16_t material = 0;
  Kind kind = Kind::free;
  Vec3 velocity{};
  Vec3 angular_velocity{};
  double mass = 0.0;    ///< 0: from the material's density, 4/3 pi r^3 rho
  double inertia = 0.0; ///< 0: 2/5 m r^2
};

struct Spheres {
  std::vector<Vec3> position;
  std::vector<Vec3> velocity;
  std::vector<Vec3> force;
  std::vector<Vec3> angular_velocity;
  std::vector<Vec3> torque;
  std::vector<double> radius;
  std::vector<double> mass;
  std::vector<double> inertia;
  std::vector<double> inv_mass;    ///< 0 for fixed spheres
  std::vector<double> inv_inertia; ///< 0 for fixed spheres
  std::vector<std::uint16_t> material;
  std::vector<Kind> kind;
  std::vector<std::uint32_t> id;     ///< stable identity
  std::vector<Image3> image;         ///< periodic boundaries crossed (all 0 without them)
  std::vector<Vec3> force_previous;  ///< velocity Verlet: F(t) while F(t + dt) is computed
  std::vector<Vec3> torque_previous; ///< velocity Verlet: the same for the torque

  std::size_t size() const { return position.size(); }
  bool empty() const { return position.empty(); }
  bool is_free(std::size_t i) const { return kind[i] == Kind::free; }
  double max_radius() const;

  /// Appends a sphere whose mass and inertia are resolved (> 0). Returns its index. A fixed
  /// sphere is at rest and feels no force; moved spheres are not there yet in 3D (refused).
  std::size_t add(const SphereSpec& spec);
};

/// Calls f with every per-sphere field of s in turn (a checkpoint's order).
template <class S, class F> void sphere_fields(S& s, F&& f) {
  f(s.position), f(s.velocity), f(s.force), f(s.angular_velocity), f(s.torque), f(s.radius);
  f(s.mass), f(s.inertia), f(s.inv_mass), f(s.inv_inertia), f(s.material), f(s.kind), f(s.id);
  f(s.image), f(s.force_previous), f(s.torque_previous);
}

} // namespace talus
