#pragma once
// The stress of an assembly of spheres from its contacts, as analysis/stress.hpp computes it in
// 2D (Love 1927, Weber 1966; Christoffersen, Mehrabadi & Nemat-Nasser 1981): the mean stress over
// a volume V is
//   sigma_ab = -(1/V) sum_c f_a l_b  +  (1/V) sum_i m_i u_a u_b,
// f the contact's force on a sphere, l the branch from the sphere's centre to the contact point
// (between two spheres the middle of their overlap, on a plate the plate's point), u a sphere's
// velocity less the mean: the contact part and the kinetic part, Pa, compression positive. The
// fabric tensor (Satake 1982; Oda 1982) is the mean of n n over the contacts between spheres.
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/vec3.hpp"
#include "engine3d/simulation3.hpp"

namespace talus {

/// A tensor of space: (x, y, z) rows and columns.
using Tensor3 = Eigen::Matrix3d;

/// The stress and structure of the spheres with their centres in a box.
struct RegionStress3 {
  Tensor3 contact = Tensor3::Zero(); ///< Pa: -(1/V) sum f l over the spheres' contacts
  /// Pa: (1/V) sum m u u, u about the spheres' mean velocity (and, in a sheared cell, less the
  /// shear's flow gamma_dot (y - <y>) along x)
  Tensor3 kinetic = Tensor3::Zero();
  Tensor3 fabric = Tensor3::Zero(); ///< mean n n over the sphere-sphere contacts (trace 1)
  std::size_t spheres = 0;          ///< free spheres with their centres in the box
  std::size_t contacts = 0;         ///< sphere-sphere contacts with a sphere in it (each once)
  double volume = 0.0;              ///< m^3
  Tensor3 total() const { return contact + kinetic; }
};

/// The principal values of a tensor's symmetric part, the largest (major) first, and the unit
/// direction of each (column k of `directions` for value k).
struct Principal3 {
  Eigen::Vector3d values = Eigen::Vector3d::Zero();
  Tensor3 directions = Tensor3::Identity();
};
Principal3 principal(const Tensor3& t);

/// The stress over the box [lo, hi]: the contacts of the free spheres with their centres in it
/// (with other spheres and with plates), its volume, and their velocities. The contact forces are
/// those the laws give in the state as it is (the springs as the last step left them).
RegionStress3 region_stress(const Simulation3& sim, Vec3 lo, Vec3 hi);

/// Each sphere's stress (Pa): -(1/V_i) sum f l over its contacts, V_i its volume 4/3 pi r^3, the
/// forces as region_stress takes them. Summed times V_i over the spheres in a region, it is the
/// region's contact part times the region's volume.
std::vector<Tensor3> sphere_stresses(const Simulation3& sim);

/// The thermo.csv columns of a region's stress, each name after a comma: the total stress's nine
/// components (stress_xx, stress_xy, ... row by row), the kinetic part's six, the pressure (a
/// third of the trace), the principal values (major, intermediate, minor), the major direction
/// (its largest component positive), and the fabric's six; each name after `prefix` (a named
/// region's).
std::string stress_thermo_header(const std::string& prefix = "");
/// The values of those columns, each after a comma.
std::string stress_thermo_columns(const RegionStress3& s);

} // namespace talus
