#pragma once
// The deforming periodic cell's controller (docs/model.md, "Deforming cell"). In the pressure
// mode the cell takes, after each step, the isotropic strain rate that would close the fraction
// `relaxation` of the mean stress' error in the next step if the grains stood still: the grains
// follow the cell affinely, so a strain changes every contact's overlap at once, and the stress
// answers it through the contacts' stiffness alone (the dampers see the grains' own velocities,
// which the remap leaves as they are).
#include "core/domain.hpp"
#include "drivers/drivers.hpp"

namespace talus {

/// What the grains of the cell say after a step: the stress the cell holds (compression
/// positive) and its stiffness against the cell's strain. Without shear that is the mean stress,
/// half the trace of the contact and kinetic stress over the cell, and its stiffness against an
/// isotropic compression, -dP/d(ln L) = (1/(2A)) sum_c k_c |d_c|^2 (k_c a contact's tangent
/// normal stiffness, d_c its branch between the centres; the forces' own turn and the area's
/// change are smaller by the overlap over the diameter and left out). A sheared cell holds the
/// normal stress across the shear, sigma_yy = (1/A)(sum_c F_y d_y + sum m u_y^2), with the
/// stiffness against a strain of y alone, (1/A) sum_c k_c d_y^4 / |d_c|^2.
struct CellReading {
  double pressure = 0.0;  ///< N/m (Pa in 3D)
  double stiffness = 0.0; ///< N/m (Pa in 3D)
};

/// Throws InvalidArgument for a pressure mode's fastest rate or relaxation out of range (in words,
/// naming the key): for a cell of disks or of spheres.
template <class V> void require_controller_keys(const CellOf<V>& c);

/// Checks a cell's keys against the box it deforms (in words, naming the key), and starts its
/// state at rest.
void attach_cell(Cell& c, const Domain& d);

struct World;

/// Throws InvalidArgument for a world with what the cell's affine remap would leave behind: wall
/// segments, grains of kind `moved` (driven or held), or a second cell. Nothing without a cell.
void require_cell_fits(const World& w);

/// The true strain rate of each side of the box in the next step, 1/s: the set one (rate mode)
/// or the controller's, along each periodic direction (pressure mode; along y alone in shear).
Vec2 cell_strain_rate(const Cell& c, const Domain& d);

/// The pressure mode's rate for the next step, from the reading after this one:
///   rate = relaxation (P - P_target) / (K dt),
/// which compresses (rate < 0) below the target; with no stiffness (no contact) the fastest
/// towards the target. Never faster than max_strain_rate either way. For a cell of disks or of
/// spheres (engine3d/cell3.hpp).
template <class V> double cell_rate(const CellOf<V>& c, const CellReading& r, double dt);

} // namespace talus
