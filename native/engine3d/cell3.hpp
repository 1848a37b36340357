#pragma once
// The deforming periodic cell of a scene of spheres (docs/model.md, "Deforming cell"): the 2D
// cell's keys and controller (drivers/cell.hpp) on three axes. The box's sides change at a set
// true strain rate, or at the rate that holds the spheres' mean stress at a pressure; every
// sphere follows the box affinely (fixed ones too), the velocities left as they are. With a
// shear rate the images across y slide along x (Lees-Edwards, domain3.hpp).
#include <cstddef>

#include "drivers/cell.hpp"
#include "engine3d/scene3.hpp"
#include "engine3d/sphere_list.hpp"
#include "materials/pair_table.hpp"

namespace talus {

using Cell3 = CellOf<Vec3>;

/// Throws InvalidArgument, in words naming the key, for a cell the box cannot take: a strain
/// rate along an axis that does not wrap; a pressure without every axis periodic (isotropic) or,
/// sheared, without x and y; a shear without x and y periodic, or with a strain rate along x;
/// plates, which do not follow the cell.
void validate(const Cell3& c, const Domain3& d, std::size_t plates);

/// validate, then starts the cell's state at rest (a fresh run's).
void attach_cell(Cell3& c, const Domain3& d, std::size_t plates);

/// The true strain rate of each side in the next step, 1/s: the set one (rate mode), or the
/// controller's along every axis (pressure mode), or along y alone (pressure mode, sheared).
Vec3 cell_strain_rate(const Cell3& c);

/// The images' slide across y for the box as it is: the shear rate times the height (0 without
/// a cell).
void set_shear_velocity(const Cell3* c, Domain3& d);

/// One step of the cell: the box's sides by exp(rate dt) about its lower corner, the
/// Lees-Edwards offset on by the slide, and every sphere (and the list's build position of each,
/// so that the drift test sees the spheres' own moves) carried with the box.
void deform_cell(Cell3& c, Domain3& d, Spheres& s, SphereList& list, double dt, int threads);

/// The offset back into [0, L_x) (at a list build: the images are the same a width further on).
void reduce_shear_offset(Domain3& d);

/// What the spheres of the cell say after a force pass (drivers/cell.hpp, CellReading): the mean
/// stress, a third of the trace of the contact and kinetic stress over the box, and its
/// stiffness against an isotropic strain, (1/(3V)) sum_c k_c |d_c|^2; sheared, the normal stress
/// across the shear, sigma_yy = (1/V)(sum_c F_y d_y + sum m u_y^2), and its stiffness against a
/// strain of y alone, (1/V) sum_c k_c d_y^4 / |d_c|^2. Compression positive, Pa. The same bits
/// for any thread count.
CellReading cell_reading(const Cell3& c, const Scene3& scene, const SphereList& list,
                         const PairTable& table, const Settings3& settings, int threads);

} // namespace talus
