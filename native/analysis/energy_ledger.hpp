#pragma once
// The energy ledger: where a run's energy went. Besides the kinetic, gravitational and elastic
// energy of the state (observables.hpp), the energy the normal dampers and friction dissipated
// and the work the driven walls did on the grains, each integrated over time from its power in
// the contacts, looked at after every step. With them the sum
//   E_kin + E_grav + E_el + dissipated - wall work
// stays at its start but for the integration's error: its drift is the run's energy error.
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/observables.hpp"
#include "simulation/simulation.hpp"

namespace talus {

/// The powers of the contacts of a state (W), and the energy of the tangential and rolling
/// springs (J).
struct ContactPowers {
  double damper = 0.0; ///< -(F_n - F_el) v_n: the normal damper's dissipation, >= 0
  /// -F_t v_t - M_r w_r: the tangential force's work against the slip and the rolling torque's
  /// against the relative spin (friction's dissipation, sliding and rolling, plus the springs'
  /// loading)
  double tangential = 0.0;
  /// the power of the contact forces on the free grains beyond the relative motion's: what moving
  /// walls and moved wall particles put in (0 at fixed walls)
  double walls = 0.0;
  double tangential_elastic = 0.0; ///< 1/2 k_t s^2 + 1/2 k_r theta^2 summed, J
};

/// Every touching contact with at least one free member, with the law of the run.
ContactPowers contact_powers(const Simulation& sim);

/// One thermo row's part of the ledger, J.
struct LedgerRow {
  double dissipated_damper = 0.0;
  double dissipated_friction = 0.0; ///< the tangential work less the springs' energy gained
  double wall_work = 0.0;           ///< done on the grains by driven walls
  /// E_total + dissipated - wall work, less its value at the start: the energy error
  double imbalance = 0.0;
  /// The imbalance's rise above its lowest at the rows before, over the energy that has been
  /// in play (the largest kinetic plus elastic energy of those rows, plus the dissipated energy
  /// and the walls' work): what an instability puts in
  double growth = 0.0;
  double rise = 0.0; ///< J: the imbalance's rise above its lowest before
};

/// The ledger's columns of thermo.csv, in 2D and 3D, each with its leading comma: their names,
/// and a row's values.
inline constexpr const char* ledger_thermo_header =
    ",dissipated_damper,dissipated_friction,wall_work,energy_imbalance";
std::string ledger_thermo_columns(const LedgerRow& row);

/// The energy growth at which a run with the ledger stops as unstable.
inline constexpr double ledger_growth_limit = 0.01;

class EnergyLedger {
public:
  /// Starts at a state of time `time` (s), total energy `total` (J) and contact powers `now` (a
  /// new run's t = 0). The ledger is the same in 2D and 3D: each engine computes its powers.
  void start(const ContactPowers& now, double time, double total);
  /// Takes in the step since the last look (trapezoidal rule on the powers).
  void observe(const ContactPowers& now, double time);
  /// The run was changed since the last look, at the same time (gravity, materials, the
  /// tangential law, walls removed with the springs of their contacts): the energy the change
  /// put in or took out, `total_now` less `total_before` (J), is the change's, not an
  /// imbalance, and the powers go on from `now`.
  void changed(const ContactPowers& now, double total_before, double total_now);
  /// The ledger at the last look, with that state's total energy and its kinetic plus elastic
  /// energy (J), as a thermo row: the growth is measured against the rows before.
  LedgerRow row(double total, double mechanical);
  /// The ledger as numbers, for a checkpoint, and back (a resumed run's ledger is the same as an
  /// uninterrupted one's).
  std::vector<double> save() const;
  void load(const std::vector<double>& state);

private:
  ContactPowers last_{};
  double last_time_ = 0.0;
  double damper_ = 0.0, tangential_ = 0.0, walls_ = 0.0; ///< J, integrated
  double start_total_ = 0.0;                             ///< E_total at the start
  double start_tangential_elastic_ = 0.0;
  double lowest_imbalance_ = 0.0, largest_mechanical_ = 0.0; ///< J, over the rows so far
};

/// The 2D engine's ledger: started at a simulation's state, taking in its steps, and a row at its
/// energies `e`.
void start_ledger(EnergyLedger& ledger, const Simulation& sim);
void observe_ledger(EnergyLedger& ledger, const Simulation& sim);
LedgerRow ledger_row(EnergyLedger& ledger, const Energies& e);

/// The first words of an energy growth's diagnosis: when, by how much, against which limit.
std::string energy_growth_words(std::uint64_t step, double time, double timestep,
                                const LedgerRow& row);

/// Why a run's energy grew: the stiffest contact now against the timestep, and against the
/// collision time the timestep was chosen for (`collision_time`, s). For the guard's message.
std::string energy_growth_diagnosis(const Simulation& sim, const LedgerRow& row,
                                    double collision_time);

} // namespace talus
