#pragma once
// ParaView files of a 3D scene: its spheres and its plates, one .vtp each per snapshot (the .pvd
// collection is vtk.hpp's).
#include <span>
#include <string>

#include "analysis/stress3.hpp"

#include "engine3d/scene3.hpp"

namespace talus {

/// The spheres as vertices with point data: id, radius, velocity, angular_velocity, force,
/// kind (0 free, 1 fixed), material, mass (ParaView's Glyph filter with a sphere, scaled by
/// radius, draws them); with `stress` (one per sphere: stress3.hpp's sphere_stresses) also its
/// nine components, row by row.
std::string vtp_spheres(const Scene3& scene, std::span<const Tensor3> stress = {});
/// The plates as quadrilaterals with the force the spheres put on each (cell data). A whole
/// plane is drawn as a square about its centre `reach` (m) on a side from it.
std::string vtp_plates(const Scene3& scene, double reach);

} // namespace talus
