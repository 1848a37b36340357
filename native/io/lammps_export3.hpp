#pragma once
// A 3D scenario (simulation.dimension = 3) as a LAMMPS case for the talus LAMMPS package: the
// spheres where the builder puts them in a data file, their exact masses, and a deck with
// pair_style granthesis in 3D, the box's plates as fix granthesis/wall planes, gravity and
// fix nve/sphere. What LAMMPS and the package do not express exactly is refused with the reason.
#include <functional>
#include <string>

#include "io/lammps_export.hpp"
#include "scenario3d/build3.hpp"
#include "scenario3d/scenario3.hpp"

namespace talus {

/// The Atoms (atom_style sphere: id type diameter density x y z, ids from 1) and Velocities
/// sections of a LAMMPS data file for the spheres, each of type type_of(i), its density the one
/// that makes read_data's 4/3 pi r^3 rho its mass.
std::string sphere_data_sections(const Spheres& p, const std::function<int(std::size_t)>& type_of);

/// Throws InvalidArgument, naming the key and what LAMMPS lacks (lever arms other than at the
/// contact point, a linear dashpot other than never_attractive, rigid materials).
void check_lammps_export(const Scenario3& s);

/// The case of a built 3D scenario; `command` is the command line that made it.
LammpsCase export_lammps(const Scenario3& s, const BuiltScenario3& built,
                         const std::string& command);

} // namespace talus
