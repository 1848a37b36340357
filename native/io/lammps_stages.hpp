#pragma once
// A deforming cell and a run in stages as LAMMPS commands, for talus export lammps
// (io/lammps_export.cpp): the cell as fix deform (a tilted, triclinic box for Lees-Edwards
// shear), and stages that change only a cell's rates as one LAMMPS `run` per stage, the cell's
// fix replaced between them.
#include <optional>
#include <string>

#include "scenario/scenario.hpp"

namespace talus {

/// Why the stages or the cell cannot be exported (naming the key and what is allowed), or
/// nothing: a stage with a condition, a stage's change of any key but a cell's strain_rate and
/// shear_rate, a cell that both strains and shears (fix deform remaps either the positions or
/// the velocities of the atoms that cross the box, not both).
std::optional<std::string> cell_and_stages_refusal(const Scenario& s);

/// Whether the cell shears in any stage: the box is then triclinic from the data file on.
bool shears_in_any_stage(const Scenario& s);

/// The deck's end: the cell's fix deform (none without a cell) and `run ${steps}`, or, for a run
/// in stages, the first stage's fix and then each stage's run, the cell's fix written again
/// before each stage that changes it. Every stage but the last lasts as natively (its duration
/// in steps, rounded up); the last lasts to the run's `steps`.
std::string cell_and_runs(const Scenario& s, bool periodic_x, bool periodic_y, double dt,
                          std::uint64_t steps);

} // namespace talus
