#include "fix_frost_heave.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>

#include <mpi.h>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "host_api.hpp"
#include "pair_coefficients.hpp"
#include "talus/frost_heave.hpp"
#include "update.h"
#include "utils.h"

namespace talus::lammps {

namespace {

constexpr const char* style_name = "fix frost/heave";
constexpr const char* usage = "usage: fix ID GROUP frost/heave epsilon E factor F table Y "
                              "[interval T] [initial_wait yes|no] [every N] [inertia disc|sphere]";

// A keyword's number: finite, and at least `lowest` (above it if `strict`).
double number(const std::string& key, const char* text, double lowest, bool strict,
              const std::string& allowed, std::string& problem) {
  const std::optional<double> x = finite_number(text);
  const bool ok = x && (strict ? *x > lowest : *x >= lowest);
  if (!ok && problem.empty()) problem = key + " = " + text + "; allowed: " + allowed;
  return x.value_or(0.0);
}

} // namespace

FixFrostHeave::FixFrostHeave(LAMMPS_NS::LAMMPS* instance, int narg, char** arg)
    : Fix(instance, narg, arg) {
  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 3;
  global_freq = 1;
  extscalar = 0;
  extvector = 0;
  restart_global = 1;
  force_reneighbor = 1;
  next_reneighbor = -1;
  nevery = 1;
  disc_ = domain->dimension == 2;
  bool has_epsilon = false, has_factor = false, has_table = false;
  std::string problem;
  std::set<std::string> given;
  for (int k = 3; k < narg; k += 2) {
    const std::string key = arg[k];
    if (k + 1 >= narg) fail(key + ": the value is missing (" + usage + ")");
    if (!given.insert(key).second)
      fail("keyword '" + key + "' is given twice; allowed: each keyword once (" + usage + ")");
    const char* value = arg[k + 1];
    if (key == "epsilon") {
      epsilon_ = number(key, value, 0.0, false, ">= 0 J", problem);
      has_epsilon = true;
    } else if (key == "factor") {
      factor_ = number(key, value, 0.0, true, "> 0", problem);
      has_factor = true;
    } else if (key == "table") {
      table_ = number(key, value, -HUGE_VAL, false, "a finite height, m", problem);
      has_table = true;
    } else if (key == "interval") {
      interval_ = number(key, value, 0.0, false, ">= 0 s", problem);
    } else if (key == "initial_wait") {
      const std::string v = value;
      if (v != "yes" && v != "no") fail("initial_wait = " + v + "; allowed: yes, no");
      // the interval counts from this step too, as if a heave had been here (the native rule)
      last_step_ = v == "yes" ? update->ntimestep : -1;
    } else if (key == "every") {
      const double n = number(key, value, 1.0, false, "an integer >= 1", problem);
      if (n != std::floor(n) && problem.empty())
        problem = "every = " + std::string(value) + "; allowed: an integer >= 1";
      nevery = static_cast<int>(n);
    } else if (key == "inertia") {
      const std::string v = value;
      if (v != "disc" && v != "sphere") fail("inertia = " + v + "; allowed: disc, sphere");
      disc_ = v == "disc";
    } else {
      fail("unknown keyword '" + key +
           "'; allowed: epsilon, factor, table, interval, initial_wait, every, inertia (" + usage +
           ")");
    }
  }
  if (!problem.empty()) fail(problem);
  if (!has_epsilon || !has_factor || !has_table)
    fail(std::string("epsilon, factor and table are required (") + usage + ")");
}

void FixFrostHeave::fail(const std::string& message, std::source_location at) const {
  talus::lammps::fail(error, style_name, message, at);
}

int FixFrostHeave::setmask() {
  return LAMMPS_NS::FixConst::END_OF_STEP;
}

void FixFrostHeave::init() {
  if (const std::string problem = units_problem(update->unit_style); !problem.empty())
    fail(problem);
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag)
    fail("needs per-atom radius, mass and angular velocity for the kinetic energy: atom_style "
         "sphere");
}

// Translational and rotational, over the group's atoms on every rank.
double FixFrostHeave::group_kinetic_energy() const {
  const double share = disc_ ? 0.5 : 0.4;
  double local = 0.0;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double* v = atom->v[i];
    const double* w = atom->omega[i];
    const double m = atom->rmass[i], r = atom->radius[i];
    local += 0.5 * m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) +
             0.5 * share * m * r * r * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  }
  double total = 0.0;
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, world);
  return total;
}

void FixFrostHeave::setup(int /*vflag*/) {
  clock_.setup(*update);
}

double FixFrostHeave::now() const {
  return clock_.now(*update);
}

void FixFrostHeave::end_of_step() {
  // the interval by whole steps since the last heave: the same decision in a resumed run
  if (last_step_ >= 0 &&
      static_cast<double>(update->ntimestep - last_step_) * update->dt < interval_)
    return;
  kinetic_ = group_kinetic_energy();
  if (!(kinetic_ < epsilon_)) return;
  heave();
  cycles_ += 1.0;
  last_time_ = now();
  last_step_ = update->ntimestep;
  // the heaved atoms may have left their ranks' boxes and their neighbours: new lists (and the
  // atoms' exchange) before the next forces
  next_reneighbor = update->ntimestep + 1;
  if (comm->me == 0) {
    char line[160];
    std::snprintf(line, sizeof line, "%s: heave %ld at t = %.9g s (step %ld)\n", style_name,
                  static_cast<long>(cycles_), last_time_, static_cast<long>(update->ntimestep));
    LAMMPS_NS::utils::logmesg(lmp, std::string(line)); // a std::string: see compat/fmt
  }
}

void FixFrostHeave::heave() {
  const int up = domain->dimension == 2 ? 1 : 2;
  for (int i = 0; i < atom->nlocal; ++i)
    if (atom->mask[i] & groupbit)
      atom->x[i][up] = talus::heaved_height(atom->x[i][up], table_, factor_);
}

double FixFrostHeave::compute_scalar() {
  return cycles_;
}

// 1: the heaves so far; 2: the time of the last one (s; -1 before the first); 3: the group's
// kinetic energy at the last test (J)
double FixFrostHeave::compute_vector(int n) {
  return n == 0 ? cycles_ : n == 1 ? last_time_ : kinetic_;
}

// The heaves, the time and step of the last one and the time now (RunClock says why the fix
// keeps its own).
void FixFrostHeave::write_restart(FILE* file) {
  if (comm->me != 0) return;
  const double state[4] = {cycles_, last_time_, static_cast<double>(last_step_), now()};
  write_fix_state(file, state, 4);
}

void FixFrostHeave::restart(char* buffer) {
  double state[4];
  std::memcpy(state, buffer, sizeof state);
  cycles_ = state[0];
  last_time_ = state[1];
  last_step_ = static_cast<LAMMPS_NS::bigint>(state[2]);
  clock_.resume(state[3]);
}

} // namespace talus::lammps
