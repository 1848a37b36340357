#pragma once
// The thesis' files (sec. 2.8-2.9): an .in file is 5 header lines (N; force law tag 0 = Hertzian
// viscoelastic, 1 = linear dashpot; t_max; dt; gravity x y z) and one line per particle of 13
// columns: x, y, angle, vx, vy, omega, mass, radius, type (0 free, 1 fixed, 2 vibrated,
// 3 pressed), mu, gamma_t, Y, A. An .out file repeats the header and appends such blocks.
#include <string>
#include <vector>

#include "scenario/scenario.hpp"
#include "simulation/simulation.hpp"

namespace talus {

struct ThesisParticle {
  double x, y, angle, vx, vy, omega, mass, radius;
  int type;
  double mu, gamma_t, young, damping;
  int line = 0; ///< its line in the file (0: not read from one)
};

struct ThesisFile {
  int force_law = 1; ///< 0: Hertzian viscoelastic, 1: linear dashpot
  double t_max = 1.0;
  double dt = 1e-6;
  double gravity[3] = {0.0, -9.81, 0.0};
  std::vector<ThesisParticle> particles;
  std::string file; ///< the file it was read from (empty: not read from one)
};

/// Whether text may follow the N particle lines: an .in file ends there; a .out file holds more
/// snapshots, each as an .in file's block.
enum class After { nothing, more_blocks };
/// Parses an .in file (or the first block of a .out file); errors name the file, the line and the
/// column.
ThesisFile read_thesis_in(const std::string& text, const std::string& file,
                          After after = After::nothing);
std::string write_thesis_in(const ThesisFile& f);

/// A scenario with the file's particles as an explicit list. The mapping: law 1 (linear) uses
/// k_n = Y and a damping rate gamma_n = A; law 0 (Hertz, F = Y sqrt(R*) sqrt(xi)(xi + A dxi/dt))
/// uses E = 3/2 Y (nu = 0, so rho = Y sqrt(R*)) and A_talus = A/1.5; gamma_t is a damping rate
/// gamma_t/m (see docs/file-formats.md). Types 2 and 3 become fixed particles: give them a driver
/// in the scenario (the thesis' vibration and press parameters are not in the file).
Scenario scenario_from_thesis(const ThesisFile& f, const std::string& name);
/// The .in file of a scenario whose particles are an explicit list (the inverse of the above).
ThesisFile thesis_from_scenario(const Scenario& s);

/// One .out block (13 columns per particle) of the current state.
std::string thesis_out_block(const Simulation& sim);
/// The .out header (5 lines).
std::string thesis_out_header(const Simulation& sim, double t_max);

} // namespace talus
