#pragma once
// What a run writes into its folder, row by row and file by file: thermo.csv's columns,
// track.csv's rows, the VTK snapshots and their collections, run.json. The run's observers
// (run/observer.hpp) decide when.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <system_error>
#include <vector>

#include "analysis/observables.hpp"
#include "run/run_book.hpp"
#include "scenario/scenario.hpp"

namespace talus::run {

/// thermo.csv's header; `ledger`: with the energy ledger's columns (output.energy_ledger);
/// with output.stress, the stress columns, then those of each of output.stress_regions.
std::string thermo_header(const RunBook& book, bool ledger, const OutputSection& output);
/// A deforming cell's columns (with a cell driver): the box's sides and the strain rate in force.
std::string cell_header();
/// Their values now ("" without a cell driver).
std::string cell_columns(const Simulation& sim);
/// The region output.stress measures: output.stress_region, or a deforming cell's box, or the
/// container's extent.
Rect stress_region(const Simulation& sim, const Scenario& s, const RunBook& book);
/// thermo.csv's stress columns (output.stress) over `region` (analysis/stress.hpp), then over
/// each of output.stress_regions.
std::string stress_columns(const Simulation& sim, const Rect& region, const OutputSection& output);
/// The columns of a thermo row before the ledger's: time, step, energies e, momenta,
/// coordination, contacts, packing fraction.
std::string thermo_columns(const Simulation& sim, const Scenario& s, const RunBook& book,
                           const Energies& e);
/// The force the grains push on a wall group (its particles and segments), N.
Vec2 group_force(const Simulation& sim, const DriverTargets& g);
/// A wall group's height: the mean y of its particles and of its segments' ends, m.
double group_height(const Simulation& sim, const DriverTargets& g);
/// The columns after the ledger's: the force on each wall group, x and y.
std::string group_force_columns(const Simulation& sim, const RunBook& book);
/// track.csv's rows of the tracked particles now.
std::string track_rows(const Simulation& sim, const std::vector<std::uint32_t>& tracked);
/// Snapshot n's files in dir/snapshots: particles, walls (if any), contacts, and with
/// `with_contacts_csv` the contacts as CSV (output.contacts); `with_stress`: the grains' stress
/// in the particles' file (output.stress).
void write_snapshot_files(const std::filesystem::path& dir, const Simulation& sim, std::uint64_t n,
                          bool with_contacts_csv, bool with_stress);
/// The ParaView collections of the snapshots taken at `times` (s), in order.
void write_collections_of(const std::filesystem::path& dir, const std::vector<double>& times,
                          bool walls);
/// run.json: `wall` seconds over every session, of which the last took `session_wall` for
/// `steps_done` steps; `ended`: why the run ended (docs/file-formats.md).
std::string run_json(const Scenario& s, const Simulation& sim, const RunBook& book, double wall,
                     double session_wall, std::uint64_t steps_done, const std::string& ended);

/// What in dir's outputs falls short of what a checkpoint vouches for (empty: nothing): a file
/// in `file_bytes` missing or shorter than its count (its tail lost: a crash before it reached
/// the disk), or one of the first `snapshots` snapshots missing. A resume from such a
/// checkpoint would leave a gap, so it is refused, never padded.
std::string outputs_short_of(const std::filesystem::path& dir,
                             const std::map<std::string, std::uint64_t>& file_bytes,
                             std::uint64_t snapshots);
/// Cuts the outputs in dir back to what a checkpoint counts: each file in `file_bytes` to its size
/// there, and the snapshots from number `snapshots` on removed. Errors go to `ec`; it goes on past
/// them.
void cut_back_outputs(const std::filesystem::path& dir,
                      const std::map<std::string, std::uint64_t>& file_bytes,
                      std::uint64_t snapshots, std::error_code& ec);

} // namespace talus::run
