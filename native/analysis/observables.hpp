#pragma once
// What can be measured on a running simulation. Sums run over free particles only: wall
// particles, fixed or moved, are boundaries, not part of the granular system.
#include <vector>

#include "core/vec2.hpp"
#include "simulation/simulation.hpp"

namespace talus {

struct Energies {
  double translational = 0.0; ///< sum 1/2 m v^2, J
  double rotational = 0.0;    ///< sum 1/2 I omega^2, J
  double elastic = 0.0;       ///< stored in contacts (normal and tangential springs), J
  double gravitational = 0.0; ///< sum -m g.r (zero at the origin), J
  double kinetic() const { return translational + rotational; }
  double total() const { return kinetic() + elastic + gravitational; }
};

Energies energies(const Simulation& sim);
/// Sum of m v over free particles, kg m/s.
Vec2 linear_momentum(const Simulation& sim);
/// Angular momentum about `point`: orbital sum m (r - point) x v plus spin sum I omega, kg m^2/s.
double angular_momentum(const Simulation& sim, Vec2 point = {});
/// Mean number of contacts per free particle (contacts with walls and wall particles included).
double coordination_number(const Simulation& sim);
/// Number of touching contacts (pairs and wall contacts).
std::size_t contact_count(const Simulation& sim);
/// Fraction of the rectangle [lo, hi] covered by free particles (exact disk-rectangle overlap);
/// in a periodic box, by the grains and their periodic images.
double packing_fraction(const Simulation& sim, Vec2 lo, Vec2 hi);
/// Area of the free grains with their centres in the disc of this centre and radius, over the
/// disc's area (a drum's filling).
double disc_area_fraction(const Simulation& sim, Vec2 centre, double radius);
/// Total force the grains put on the given wall particles (fixed or moved), N.
Vec2 force_on_particles(const Simulation& sim, const std::vector<std::uint32_t>& indices);

/// One touching contact with its forces, for force chains and force distributions.
struct ContactRecord {
  std::uint32_t i = 0;
  std::int64_t j = -1;  ///< the other particle, or -1 - segment index for a wall
  Vec2 from;            ///< centre of i
  Vec2 to;              ///< centre of j (its periodic image), or the contact point on the wall
  Vec2 point;           ///< the contact point: the middle of the overlap, on the line of centres
  double overlap = 0.0; ///< xi, m
  double overlap_rate = 0.0;     ///< d xi / dt, m/s (> 0 while approaching)
  double m_eff = 0.0;            ///< kg: the pair's reduced mass (the grain's against a wall)
  double normal_force = 0.0;     ///< N
  double tangential_force = 0.0; ///< N, signed along t
  Vec2 force;                    ///< N: the contact's force on i (on j: its opposite)
  double elastic_force = 0.0;    ///< N: the normal law's force at this overlap without motion
  double stiffness = 0.0;        ///< N/m: its slope d F_el / d xi here
};

/// Every touching contact with its normal and tangential force (the law of the run).
std::vector<ContactRecord> contact_forces(const Simulation& sim);

/// Area of the intersection of the disk (centre c, radius r) with the rectangle [lo, hi].
double disk_rectangle_area(Vec2 c, double r, Vec2 lo, Vec2 hi);

} // namespace talus
