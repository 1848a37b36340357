#pragma once
// The deforming periodic cell's keys and state, for a box of disks (drivers.hpp's Cell) or of
// spheres (engine3d/cell3.hpp's Cell3).

namespace talus {

/// A periodic cell that deforms (docs/model.md, "Deforming cell"): its lengths change at a set
/// true strain rate, or at the rate a controller takes to hold the grains' mean stress at
/// `pressure` (drivers/cell.hpp; the normal stress across the shear when sheared). Every step the
/// grains' positions follow the cell affinely (LAMMPS' fix deform with remap x); their velocities
/// are left as they are. It has no targets: it moves the box, and with it every grain. With a
/// `shear_rate` its images across y slide along x (Lees-Edwards, docs/model.md): simple shear, at a
/// set height or with the height held at a normal stress `pressure`.
///
/// The same cell deforms a box of spheres in 3D (V = Vec3: engine3d/cell3.hpp), its pressure a
/// stress in Pa.
template <class V> struct CellOf {
  V strain_rate{};              ///< 1/s: d(ln L)/dt along each axis, the rate mode
  double pressure = 0.0;        ///< N/m (Pa in 3D): the mean stress wanted (> 0), or 0: rate mode
  double max_strain_rate = 0.0; ///< 1/s: the pressure mode's fastest rate, either way
  double relaxation = 0.5;      ///< pressure mode: the fraction of the error closed per step
  double rate = 0.0;            ///< 1/s: the pressure mode's rate, chosen after the last step
  V strain{};                   ///< ln(L / L_start) along each axis since start_time
  double shear_rate = 0.0;      ///< 1/s: dv_x/dy of the images across y (Lees-Edwards), or 0
  double shear_strain = 0.0;    ///< the shear rate's integral since start_time
};

} // namespace talus
