#pragma once
// thermo.csv of a 3D run: a row of energies, contacts and list builds, then the force on each of
// the box's plates and on the fixed spheres of a rough floor, and each servo's displacement; with
// output.energy_ledger the ledger's columns (its powers taken in after every step), and with
// output.stress the stress, fabric and structure of the stress region and of each named region.
#include <optional>
#include <string>
#include <vector>

#include "analysis/energy_ledger.hpp"
#include "engine3d/simulation3.hpp"
#include "scenario3d/scenario3.hpp"

namespace talus::cli {

class Thermo3 {
public:
  /// `ledger_state`: the ledger as a checkpoint saved it (empty for a fresh run).
  Thermo3(const Scenario3& s, const std::vector<double>& ledger_state);
  void start(const Simulation3& sim);
  /// Takes in the ledger's powers after a step.
  void look(const Simulation3& sim);
  /// The ledger's state for a checkpoint (empty without one).
  std::vector<double> save() const;
  std::string header() const;
  /// Throws InstabilityError where the ledger finds energy from nowhere.
  std::string row(const Simulation3& sim, double collision_time);

private:
  std::optional<EnergyLedger> ledger_;
  std::vector<std::string> plate_names_; // the box's sides, the scene's plates' order
  std::vector<std::string> servo_names_; // the servos' sides, the scene's servos' order
  bool fixed_spheres_ = false;           // a rough floor's: the force on them all
  bool cell_ = false;           // a deforming cell's columns; the default region follows it
  bool default_region_ = false; // the first region is the default: it follows servos or the cell
  std::vector<std::pair<std::string, Region3>> regions_; // column prefix, region
};

} // namespace talus::cli
