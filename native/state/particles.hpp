#pragma once
// Particles as a structure of arrays: one vector per field, indexed by particle.
#include <cstdint>
#include <vector>

#include "core/vec2.hpp"

namespace talus {

/// How a particle moves.
enum class Kind : std::uint8_t {
  free = 0,  ///< integrated from the forces on it (thesis type 0)
  fixed = 1, ///< a wall particle: feels no force, never moves (thesis type 1)
  moved = 2, ///< a wall particle whose motion a driver prescribes (thesis types 2 and 3)
};

/// How mass and moment of inertia follow from radius and density.
enum class Shape : std::uint8_t {
  disk = 0,   ///< m = rho pi r^2 t (t: thickness), I = m r^2 / 2
  sphere = 1, ///< m = 4/3 pi r^3 rho, I = 2/5 m r^2, moving in the plane
};

/// Mass of a particle of the given shape. `thickness` applies to disks only.
double shape_mass(Shape shape, double radius, double density, double thickness = 1.0);
/// Moment of inertia about the particle's centre, for rotation in the plane.
double shape_inertia(Shape shape, double mass, double radius);

/// Higher time derivatives the Gear predictor-corrector keeps (empty with velocity Verlet).
struct GearDerivatives {
  std::vector<Vec2> r2, r3, r4;         ///< acceleration, 3rd and 4th derivative of position
  std::vector<double> phi2, phi3, phi4; ///< the same for the angle
  bool empty() const { return r2.empty(); }
};

/// The periodic images a particle has crossed into, per direction: its unwrapped position is
/// its position plus these times the box's lengths (LAMMPS' image flags).
struct Image {
  std::int32_t x = 0, y = 0;
  bool operator==(const Image&) const = default;
};

/// What it takes to add one particle.
struct ParticleSpec {
  Vec2 position;
  double radius = 0.0;
  std::uint16_t material = 0;
  Kind kind = Kind::free;
  Shape shape = Shape::disk;
  Vec2 velocity{};
  double angle = 0.0;
  double angular_velocity = 0.0;
  double mass = 0.0;    ///< 0: from shape and the material's density
  double inertia = 0.0; ///< 0: from shape and mass
};

struct Particles {
  std::vector<Vec2> position;
  std::vector<Vec2> velocity;
  std::vector<Vec2> force;
  std::vector<double> angle;
  std::vector<double> angular_velocity;
  std::vector<double> torque;
  std::vector<double> radius;
  std::vector<double> mass;
  std::vector<double> inertia;
  std::vector<double> inv_mass;    ///< 0 for fixed and moved particles
  std::vector<double> inv_inertia; ///< 0 for fixed and moved particles
  std::vector<std::uint16_t> material;
  std::vector<Kind> kind;
  std::vector<std::uint32_t> id; ///< stable identity: survives any reordering
  std::vector<Image> image;      ///< periodic boundaries crossed (all 0 without them)
  GearDerivatives gear;
  std::vector<Vec2> force_previous;    ///< velocity Verlet: F(t) while F(t + dt) is computed
  std::vector<double> torque_previous; ///< velocity Verlet: the same for the torque

  std::size_t size() const { return position.size(); }
  bool empty() const { return position.empty(); }
  bool is_free(std::size_t i) const { return kind[i] == Kind::free; }
  std::size_t count(Kind k) const;
  double max_radius() const;
  double min_radius() const;

  /// Holds particle i (Kind::moved: placed by an outside model, such as frost, not integrated)
  /// or frees it (Kind::free). Either way it is left at rest, with no integrator history.
  void set_held(std::size_t i, bool held);

  /// Appends a particle with mass and inertia already resolved (> 0). Returns its index.
  std::size_t add(const ParticleSpec& spec);
  void reserve(std::size_t n);
  /// Renumbers the particles: the new particle k is the old particle order[k] (every field,
  /// the integrators' history included). `order` must be a permutation of 0 .. size()-1.
  /// `threads` share the copying (the result is the same for any count).
  void permute(const std::vector<std::uint32_t>& order, int threads = 1);

  /// Calls f(vector) for every per-particle field of the particles' state (position to id),
  /// in a fixed order: the checkpoint's. Every code that handles each field (checkpoints,
  /// renumbering, copying, memory) goes through these, so a new field is never left out.
  template <class F> void for_each_state_field(F&& f) { fields_of_state(*this, f); }
  template <class F> void for_each_state_field(F&& f) const { fields_of_state(*this, f); }
  /// The same for the integrators' history (Gear's derivatives, Verlet's previous force and
  /// torque; the fields of the integrator not in use are empty).
  template <class F> void for_each_integrator_field(F&& f) { fields_of_integrator(*this, f); }
  template <class F> void for_each_integrator_field(F&& f) const { fields_of_integrator(*this, f); }
  /// Both: the state's fields, then the integrators'.
  template <class F> void for_each_field(F&& f) {
    for_each_state_field(f);
    for_each_integrator_field(f);
  }
  template <class F> void for_each_field(F&& f) const {
    for_each_state_field(f);
    for_each_integrator_field(f);
  }

private:
  template <class P, class F> static void fields_of_state(P& p, F& f) {
    f(p.position), f(p.velocity), f(p.force), f(p.angle), f(p.angular_velocity), f(p.torque);
    f(p.radius), f(p.mass), f(p.inertia), f(p.inv_mass), f(p.inv_inertia), f(p.material);
    f(p.kind), f(p.id), f(p.image);
  }
  template <class P, class F> static void fields_of_integrator(P& p, F& f) {
    f(p.gear.r2), f(p.gear.r3), f(p.gear.r4), f(p.gear.phi2), f(p.gear.phi3), f(p.gear.phi4);
    f(p.force_previous), f(p.torque_previous);
  }
};

} // namespace talus
