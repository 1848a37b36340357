#pragma once
// ParaView files: one .vtp (VTK XML PolyData) per snapshot, and a .pvd collection over time.
#include <string>
#include <utility>
#include <vector>

#include "simulation/simulation.hpp"

namespace talus {

/// The particles as vertices with point data: id, radius, velocity, angular_velocity, force,
/// kind (0 free, 1 fixed, 2 moved), material; with `stress`, each grain's contact stress
/// (analysis/stress.hpp: a 3x3 tensor, N/m, compression positive). Walls go in a separate file
/// (vtp_walls).
std::string vtp_particles(const Simulation& sim, bool stress = false);
/// The segment walls as lines, with the force the grains put on each.
std::string vtp_walls(const Simulation& sim);
/// The contacts as lines between the centres (to the contact point for walls), with cell arrays
/// normal_force and tangential_force (N), overlap (m), contact_point, and the ids of particle and
/// partner (-1 - segment for a wall): force chains in ParaView.
std::string vtp_contacts(const Simulation& sim);
/// A .pvd collection: (time, file name relative to the .pvd) in order.
std::string pvd_collection(const std::vector<std::pair<double, std::string>>& entries);

} // namespace talus
