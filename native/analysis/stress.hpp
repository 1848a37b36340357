#pragma once
// The stress of a granular assembly from its contacts (Love 1927, Weber 1966; Christoffersen,
// Mehrabadi & Nemat-Nasser 1981): the mean stress over an area A is
//   sigma_ab = -(1/A) sum_c f_a l_b  +  (1/A) sum_i m_i u_a u_b,
// f the contact's force on a grain, l the branch from the grain's centre to the contact point,
// u a grain's velocity less the mean: the contact part and the kinetic (streaming) part.
// Compression is positive, as in soil mechanics. In 2D the stress is a force per length of the
// plane, N/m (divide by the disks' thickness for Pa). The fabric tensor (Satake 1982; Oda
// 1982) is the mean of n n over the contacts between grains.
#include <cstddef>
#include <vector>

#include <Eigen/Dense>

#include "core/vec2.hpp"
#include "simulation/simulation.hpp"

namespace talus {

/// A tensor of the plane: (x, y) rows and columns.
using Tensor2 = Eigen::Matrix2d;

/// The stress and structure of the grains with their centres in a region.
struct RegionStress {
  Tensor2 contact = Tensor2::Zero(); ///< N/m: -(1/A) sum f l over the grains' contacts
  Tensor2 kinetic = Tensor2::Zero(); ///< N/m: (1/A) sum m u u, u about the grains' mean velocity
  Tensor2 fabric = Tensor2::Zero();  ///< mean n n over the grain-grain contacts (trace 1)
  std::size_t grains = 0;            ///< free grains with their centres in the region
  std::size_t contacts = 0;          ///< grain-grain contacts with a grain in it (each once)
  double area = 0.0;                 ///< m^2
  Tensor2 total() const { return contact + kinetic; }
};

/// The principal values of a tensor's symmetric part, the larger (major) first, and the major
/// direction's angle from the x axis, rad in (-pi/2, pi/2].
struct Principal {
  double major = 0.0, minor = 0.0, angle = 0.0;
};
Principal principal(const Tensor2& t);

/// The stress over the rectangle [lo, hi]: the contacts of the free grains with their centres in
/// it (with other grains, wall particles and walls), their area, and their velocities.
RegionStress region_stress(const Simulation& sim, Vec2 lo, Vec2 hi);

/// Each particle's contact stress, -(1/(pi r^2)) sum f l over its contacts (0 for a wall
/// particle): the Love-Weber stress of one grain, whose sum weighted by the areas is the
/// region's contact part.
std::vector<Tensor2> particle_stresses(const Simulation& sim);

} // namespace talus
