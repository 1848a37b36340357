#pragma once
// A native scenario as a LAMMPS case for the talus LAMMPS package (lammps-package/): a data file
// with the grains and wall particles after the scenario's packing, an include file with their
// exact masses, and an input deck with pair_style granthesis, the materials as pair_coeff lines,
// the drivers as fix move, the wall segments as fix granthesis/wall and the uniform frost rule as
// fix frost/heave. Only what LAMMPS and the
// package express exactly is exported; anything else is refused with the reason.
#include <string>

#include "scenario/build.hpp"
#include "scenario/scenario.hpp"

namespace talus {

struct LammpsCase {
  std::string name;     ///< the files are in.NAME, data.NAME and masses.NAME
  std::string deck;     ///< the input script
  std::string data;     ///< read_data's file
  std::string masses;   ///< `set atom ID mass M` for every atom (read_data can only give densities)
  std::string scenario; ///< the resolved scenario: `talus run` of it builds the same system
};

/// Throws InvalidArgument, naming the key and what LAMMPS lacks, for a scenario that cannot be
/// exported: the lever arm at the radius, rigid materials, the freezing-front frost model. Cheap: call it before building (a packing can take minutes).
void check_lammps_export(const Scenario& s);

/// The case of a built scenario. `command` is the command line that made it (quoted in the
/// deck's header). Throws InvalidArgument as check_lammps_export does, for a wall particle
/// moved by two drivers, and for a vibrating wall segment.
LammpsCase export_lammps(const Scenario& s, const BuiltScenario& built, const std::string& command);

/// Writes the case's files (and scenario.toml) into dir (created if missing; files of the same
/// names are replaced, each atomically).
void write_lammps_case(const LammpsCase& c, const std::string& dir);

} // namespace talus
