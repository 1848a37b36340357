#pragma once
// The energy ledger of a run of spheres (energy_ledger.hpp): the same bookkeeping, with the
// powers of the 3D engine's contacts.
#include <string>

#include "analysis/energy_ledger.hpp"
#include "engine3d/simulation3.hpp"

namespace talus {

/// Every touching contact with at least one free member, with the law of the run: the same
/// powers as the 2D engine's, with vector forces, torques and spins.
ContactPowers contact_powers(const Simulation3& sim);

/// The ledger started at, and taking in, a run of spheres; a row at its energies `e`.
void start_ledger(EnergyLedger& ledger, const Simulation3& sim);
void observe_ledger(EnergyLedger& ledger, const Simulation3& sim);
LedgerRow ledger_row(EnergyLedger& ledger, const Energies3& e);

/// Why a run of spheres' energy grew: when and by how much, its deepest contact now, and the
/// timestep against the collision time it was chosen for (`collision_time`, s).
std::string energy_growth_diagnosis(const Simulation3& sim, const LedgerRow& row,
                                    double collision_time);

} // namespace talus
