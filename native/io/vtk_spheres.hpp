#pragma once
// ParaView files of a 3D scene: its spheres and its plates, one .vtp each per snapshot (the .pvd
// collection is vtk.hpp's).
#include <span>
#include <string>

#include "analysis/stress3.hpp"

#include "engine3d/scene3.hpp"
#include "engine3d/simulation3.hpp"

namespace talus {

/// The spheres as vertices with point data: id, radius, velocity, angular_velocity, force,
/// kind (0 free, 1 fixed), material, mass (ParaView's Glyph filter with a sphere, scaled by
/// radius, draws them), and the box in field data (`box`: lo and hi, `periodic`: 0 or 1 per
/// axis, `shear_velocity`: m/s, Lees-Edwards' slide of the image above); with `stress` (one per
/// sphere: stress3.hpp's sphere_stresses) also its nine components, row by row.
std::string vtp_spheres(const Scene3& scene, std::span<const Tensor3> stress = {});
/// The plates as quadrilaterals with the force the spheres put on each (cell data). A whole
/// plane is drawn as a square about its centre `reach` (m) on a side from it.
std::string vtp_plates(const Scene3& scene, double reach);
/// The touching contacts as lines from a sphere's centre to its partner's (the image beside it)
/// or to the plate's point, with cell arrays normal_force and tangential_force (N), overlap (m),
/// contact_point (m), force (N, on `particle`; on `partner` its opposite), and the ids of
/// particle and partner (-1 - the plate's index for a plate), as 2D's contacts (io/vtk.hpp).
std::string vtp_contacts3(const Simulation3& sim);

} // namespace talus
