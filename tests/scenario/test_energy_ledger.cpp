// output.energy_ledger: the dissipation of two-disk and disk-on-wall impacts against the
// restitution's closed form, and the balance E_kin + E_grav + E_el + dissipated - wall work of a
// frictional settling and of driven walls (a pressing lid's segments, vibrated wall particles)
// staying at its start within the integration's error; a resumed run's ledger is the same.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/run/run_loop.hpp"
#include "io/checkpoint.hpp"
#include "scenario/build.hpp"
#include "scenario/file/load.hpp"
#include "support/builtin_scenario.hpp"
#include "support/impacts_scenario.hpp"
#include "support/run_dir.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;

namespace talus {
namespace {

using testing::builtin;
using testing::fresh_dir;

// thermo.csv's rows by column name
std::vector<std::map<std::string, double>> thermo_rows(const fs::path& dir) {
  std::istringstream in(read_file((dir / "thermo.csv").string()));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::istringstream h(line); std::getline(h, line, ',');) names.push_back(line);
  std::vector<std::map<std::string, double>> rows;
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    auto& row = rows.emplace_back();
    for (std::size_t k = 0; k < names.size() && std::getline(cells, line, ','); ++k)
      row[names[k]] = std::stod(line);
  }
  return rows;
}

std::vector<std::map<std::string, double>> run_rows(const Scenario& s, const std::string& name) {
  const fs::path dir = fresh_dir(name);
  cli::RunOptions o;
  o.quiet = true;
  cli::start_run(s, build_scenario(s), dir.string(), o);
  auto rows = thermo_rows(dir);
  fs::remove_all(dir);
  return rows;
}

double kinetic(const std::map<std::string, double>& r) {
  return r.at("kinetic_translational") + r.at("kinetic_rotational");
}

// The two impacts of support/impacts_scenario.hpp, at t_c / 500, with Gear.
Scenario ledger_impacts(const std::string& law, double restitution, double v) {
  return testing::two_impacts(law, restitution, v, "gear",
                              "energy_ledger = true\nthermo_interval = 0.001\n"
                              "snapshot_interval = 0");
}

// Elastic Hertz impacts: the dampers do nothing, and the energy after both impacts is the
// energy before. Hertz converges at second order; at t_c / 500 the restitution is off by about
// 1e-6 (docs/accuracy.md), so the energy by about 2e-6: 1e-5 leaves room and still fails a
// ledger that missed a contact for a single step.
TEST(EnergyLedger, ElasticHertzImpactsDissipateNothingAndBalance) {
  const auto rows = run_rows(ledger_impacts("hertz", 1.0, 0.1), "ledger_elastic");
  const auto &first = rows.front(), &last = rows.back();
  const double k0 = kinetic(first);
  EXPECT_EQ(first.at("energy_imbalance"), 0.0);
  EXPECT_LE(std::abs(last.at("dissipated_damper")), 1e-12 * k0);
  EXPECT_LE(std::abs(last.at("dissipated_friction")), 1e-12 * k0);
  EXPECT_LE(std::abs(last.at("wall_work")), 1e-12 * k0);
  EXPECT_NEAR(kinetic(last) / k0, 1.0, 1e-5);
  EXPECT_LE(std::abs(last.at("energy_imbalance")), 1e-5 * k0);
}

// Damped linear impacts at e = 0.5: the dampers take (1 - e^2) of the energy of the approach. The
// dashpot's force starts at eta u at the touch, between two steps: the integrator's velocity and
// the ledger's trapezoidal rule each miss up to half a step of that power, eta u^2 dt / 2, or
// 2 zeta pi dt / t_c = 3.2e-3 of the impact's energy (zeta = 0.255 at e = 0.5): 7e-3 for both.
TEST(EnergyLedger, DampedLinearImpactsDissipateWhatTheRestitutionSays) {
  const double e = 0.5;
  const auto rows = run_rows(ledger_impacts("linear", e, 0.1), "ledger_damped");
  const auto &first = rows.front(), &last = rows.back();
  const double k0 = kinetic(first);
  EXPECT_NEAR(last.at("dissipated_damper") / k0, 1.0 - e * e, 7e-3);
  EXPECT_NEAR((kinetic(last) + last.at("dissipated_damper")) / k0, 1.0, 7e-3);
  EXPECT_LE(std::abs(last.at("energy_imbalance")), 7e-3 * k0);
}

std::vector<std::string> small_silo(const std::string& integrator) {
  return {"particles.count=150",         "geometry.width=0.12",
          "geometry.height=0.25",        "simulation.duration=0.3",
          "packing.settle_max_time=0.3", "simulation.integrator=" + integrator,
          "output.energy_ledger=true",   "output.snapshot_interval=0",
          "output.picture=false"};
}

// A small silo discharging onto its floor, frictional (Cundall-Strack), with gravity: all the
// energy released goes to the dampers and to friction, but for the integration's error. Gear's
// imbalance stays near 1e-4 of the dissipated energy, velocity Verlet's near 2e-3 (its damping
// and friction forces use the velocity half a step behind: first order): 5e-4 and 5e-3.
TEST(EnergyLedger, FrictionalSilosDissipationBalancesTheEnergyReleased) {
  for (const auto& [integrator, tolerance] : {std::pair{"gear", 5e-4}, {"verlet", 5e-3}}) {
    SCOPED_TRACE(integrator);
    const auto rows = run_rows(builtin("silo_discharge", small_silo(integrator)), "ledger_silo");
    const auto& last = rows.back();
    const double dissipated = last.at("dissipated_damper") + last.at("dissipated_friction");
    EXPECT_GT(last.at("dissipated_damper"), 0.0);
    EXPECT_GT(last.at("dissipated_friction"), 0.0);
    EXPECT_NEAR(dissipated, rows.front().at("total") - last.at("total"), tolerance * dissipated);
    EXPECT_LE(std::abs(last.at("wall_work")), 1e-12 * dissipated); // its walls stand still
    EXPECT_LE(std::abs(last.at("energy_imbalance")), tolerance * dissipated);
  }
}

// Driven walls put energy in: the grain press' lid (moving segments) and the vibrated silo's
// wall particles. The balance holds within 1e-4 of the walls' work (Gear; both measure within
// 4e-5).
TEST(EnergyLedger, DrivenWallsWorkBalancesTheEnergyGainedAndDissipated) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases{
      {"force_network", {"simulation.duration=0.2"}},
      {"silo_shake", {"simulation.duration=0.1", "particles.count=150"}}};
  for (auto [name, set] : cases) {
    SCOPED_TRACE(name);
    for (const char* k : {"output.energy_ledger=true", "output.snapshot_interval=0",
                          "output.picture=false", "output.pictures=[]", "output.movie=false"})
      set.push_back(k);
    const auto rows = run_rows(builtin(name, set), "ledger_" + name);
    const auto& last = rows.back();
    const double work = last.at("wall_work");
    EXPECT_GT(work, 0.0);
    EXPECT_GT(last.at("dissipated_damper") + last.at("dissipated_friction"), 0.0);
    EXPECT_LE(std::abs(last.at("energy_imbalance")), 1e-4 * work);
  }
}

// inputs/hard/dense_compression with Gear: the press stiffens the Hertz contacts past what Gear
// integrates at the timestep chosen for an impact, and the energy grows with no overlap near
// the overlap guard's limit. The ledger's guard stops the run and names the cause.
TEST(EnergyLedger, EnergyFromNowhereStopsTheRunNamingTheStiffenedContacts) {
  Scenario s = load_scenario_file(std::string(TALUS_SOURCE_DIR) +
                                  "/inputs/hard/dense_compression/scenario.toml");
  s.simulation.integrator = Integrator::gear;
  s.output.energy_ledger = true;
  const fs::path dir = fresh_dir("ledger_growth");
  cli::RunOptions o;
  o.quiet = true;
  try {
    cli::start_run(s, build_scenario(s), dir.string(), o);
    ADD_FAILURE() << "the run did not stop";
  } catch (const InstabilityError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("that no damper, friction or driven wall accounts for"), std::string::npos)
        << what;
    EXPECT_NE(what.find("The contacts have stiffened"), std::string::npos) << what;
  }
  const std::string json = read_file((dir / "run.json").string());
  EXPECT_NE(json.find("\"ended_by\": \"unstable\""), std::string::npos);
  // the rate of the steps it did, not 0
  EXPECT_EQ(json.find("\"particle_steps_per_second\": 0,"), std::string::npos) << json;
  fs::remove_all(dir);
}

// Stopped and resumed, the ledger goes on as if never stopped: thermo.csv to the bit.
TEST(EnergyLedger, AResumedRunsLedgerIsTheSame) {
  const Scenario s =
      builtin("force_network",
              {"simulation.duration=0.1", "output.energy_ledger=true", "output.snapshot_interval=0",
               "output.picture=false", "output.checkpoint_interval=0.02"});
  const fs::path whole = fresh_dir("ledger_whole"), parts = fresh_dir("ledger_parts");
  cli::RunOptions o;
  o.quiet = true;
  cli::start_run(s, build_scenario(s), whole.string(), o);
  o.stop_at = 0.05;
  ASSERT_EQ(cli::start_run(s, build_scenario(s), parts.string(), o), cli::exit_stopped);
  o.stop_at = -1.0;
  ASSERT_EQ(cli::resume_run(parts.string(), o), cli::exit_completed);
  EXPECT_EQ(read_file((parts / "thermo.csv").string()), read_file((whole / "thermo.csv").string()));
  fs::remove_all(whole);
  fs::remove_all(parts);
}

} // namespace
} // namespace talus
