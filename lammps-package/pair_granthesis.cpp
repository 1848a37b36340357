#include "pair_granthesis.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

#include <mpi.h>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "host_api.hpp"
#include "memory.h"
#include "neigh_list.h"
#include "pair_coefficients.hpp"
#include "talus/contact_force.hpp"
#include "talus/error.hpp"
#include "talus/material_keys.hpp"
#include "talus/rolling_resistance.hpp"
#include "timestep_check.hpp"
#include "update.h"

namespace talus::lammps {

namespace {

constexpr const char* style_name = "pair granthesis";
constexpr const char* history_fix_id = "GRANTHESIS_HISTORY";
constexpr const char* rolling_fix_id = "GRANTHESIS_ROLLING";
// the first int of the settings in a restart file: its format (one with rolling resistance's
// keys); files from before it began with a law's number, 0 or more
constexpr int restart_format = -3;

} // namespace

PairGranthesis::PairGranthesis(LAMMPS_NS::LAMMPS* instance) : HostPair(instance) {
  single_enable = 1;
  single_extra = 6;
  svector = svector_storage_;
  restartinfo = 1;
  no_virial_fdotr_compute = 1;
}

PairGranthesis::~PairGranthesis() {
  svector = nullptr; // ours, not allocated by Pair
  if (history_) remove_springs_fix(history_fix_id);
  if (rolling_fix_) remove_springs_fix(rolling_fix_id);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

void PairGranthesis::fail(const std::string& message, std::source_location at) const {
  talus::lammps::fail(error, style_name, message, at);
}

void PairGranthesis::allocate() {
  allocated = 1;
  ntypes_ = atom->ntypes;
  memory->create(setflag, ntypes_ + 1, ntypes_ + 1, "pair:setflag");
  memory->create(cutsq, ntypes_ + 1, ntypes_ + 1, "pair:cutsq");
  for (int i = 0; i <= ntypes_; ++i)
    for (int j = 0; j <= ntypes_; ++j) setflag[i][j] = 1; // see given_
  material_.assign(static_cast<std::size_t>(ntypes_) + 1, Material{});
  pair_.assign(static_cast<std::size_t>(ntypes_ + 1) * static_cast<std::size_t>(ntypes_ + 1), {});
  explicit_pair_.assign(pair_.size(), 0);
  given_.assign(static_cast<std::size_t>(ntypes_) + 1, 0);
}

const PairParameters& PairGranthesis::parameters(int i, int j) const {
  return pair_[slot(i, j)];
}

// pair_style granthesis NORMAL TANGENTIAL [impact_speed V] [history_slots K] [inertia I]
void PairGranthesis::settings(int narg, char** arg) {
  const std::string tangential_names = host_tangential_law_names();
  const std::string usage =
      "usage: pair_style granthesis NORMAL TANGENTIAL [impact_speed V] [history_slots K] "
      "[inertia disc|sphere]; NORMAL: " +
      law_names<NormalLaw>() + "; TANGENTIAL: " + tangential_names +
      "; V: the impact speed (m/s, > 0, default 1) at which a Hertz damping left to be derived "
      "(hertz_damping -1) reaches the restitution; K: the contacts an atom may have at once with "
      "a law that keeps a spring (1 to 1000, default 16); inertia: the grains' moment of "
      "inertia for the rolling resistance's damping (default disc in 2d, sphere in 3d)";
  if (narg < 2 || narg % 2 != 0) fail(usage);
  try {
    normal_ = parse_normal_law(arg[0]);
    tangential_ = parse_tangential_law(arg[1]);
  } catch (const InvalidArgument& e) {
    fail(std::string(e.what()) + " (" + usage + ")");
  }
  if (!host_keeps_springs && keeps_history(tangential_))
    fail("tangential law '" + std::string(arg[1]) +
         "' keeps a contact history, which this pair style stores in LAMMPS only; allowed in "
         "LIGGGHTS: " +
         host_tangential_law_names());
  impact_speed_ = 1.0;
  history_slots_ = 16;
  inertia_ = 0;
  std::set<std::string> given;
  for (int k = 2; k < narg; k += 2) {
    const std::string key = arg[k];
    if (!given.insert(key).second)
      fail("keyword '" + key + "' is given twice; allowed: each keyword once (" + usage + ")");
    const std::optional<double> v = finite_number(arg[k + 1]);
    if (key == "inertia" &&
        (std::string(arg[k + 1]) == "disc" || std::string(arg[k + 1]) == "sphere"))
      inertia_ = std::string(arg[k + 1]) == "disc" ? 1 : 2;
    else if (key == "impact_speed" && v && *v > 0.0)
      impact_speed_ = *v;
    else if (key == "history_slots" && v && *v >= 1.0 && *v <= 1000.0 && *v == int(*v))
      history_slots_ = static_cast<int>(*v);
    else
      fail(key + " = " + arg[k + 1] + " (" + usage + ")");
  }
}

// pair_coeff I J key value ...: I = J (or a range through both) sets the materials of those types;
// I != J gives the pair's own parameters, as if both grains were of the material described.
void PairGranthesis::coeff(int narg, char** arg) {
  if (narg < 2)
    fail("usage: pair_coeff I J key value ... (keys: " + pair_coefficient_names() + ")");
  if (!allocated) allocate();
  int ilo = 0, ihi = 0, jlo = 0, jhi = 0;
  type_bounds(lmp, arg[0], atom->ntypes, ilo, ihi);
  type_bounds(lmp, arg[1], atom->ntypes, jlo, jhi);
  Material m;
  try {
    m = parse_pair_coefficients(std::vector<std::string>(arg + 2, arg + narg));
  } catch (const InvalidArgument& e) {
    fail(e.what());
  }
  int count = 0;
  for (int i = ilo; i <= ihi; ++i)
    for (int j = std::max(jlo, i); j <= jhi; ++j) {
      const std::size_t ij = slot(i, j);
      if (i == j) {
        material_[static_cast<std::size_t>(i)] = m;
      } else {
        pair_[ij] = mix(m, m, impact_speed_);
        explicit_pair_[ij] = 1;
      }
      if (i == j) given_[static_cast<std::size_t>(i)] = 1;
      ++count;
    }
  if (count == 0) fail("pair_coeff " + std::string(arg[0]) + " " + arg[1] + " names no type pair");
}

// pair_modify: LAMMPS' mixing rules (geometric, arithmetic, sixthpower) are for epsilon and
// sigma; this style mixes its materials by the rules of talus/pair_parameters.hpp, or takes the
// pair's own parameters from pair_coeff I J, so `mix` would be ignored and is refused.
void PairGranthesis::modify_params(int narg, char** arg) {
  for (int k = 0; k < narg; ++k)
    if (std::string(arg[k]) == "mix")
      fail("pair_modify mix would have no effect: two types' pair mixes their materials by "
           "talus' own rules (lammps-package/README.md, Mixing); allowed: leave mix out, or give "
           "the pair its own parameters with pair_coeff I J key value ...");
  Pair::modify_params(narg, arg);
}

void PairGranthesis::init_style() {
  if (const std::string problem = units_problem(update->unit_style); !problem.empty())
    fail(problem);
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    fail("needs per-atom radius, mass, angular velocity and torque: atom_style sphere");
  if (comm->ghost_velocity == 0) fail("needs the velocities of ghost atoms: comm_modify vel yes");
  if (!allocated)
    fail("no pair_coeff given (pair_coeff I I key value ...; keys: " + pair_coefficient_names() +
         ")");
  // a sub-style of pair_style hybrid computes only the type pairs given to it: init_one names
  // those of its pairs that lack a material
  const bool whole = force->pair == this;
  if (!whole) check_hybrid();
  for (int i = 1; i <= ntypes_; ++i) {
    if (given_[static_cast<std::size_t>(i)] == 0) {
      if (!whole) continue;
      fail("no pair_coeff for type " + std::to_string(i) + " (pair_coeff " + std::to_string(i) +
           " " + std::to_string(i) + " key value ...; keys: " + pair_coefficient_names() + ")");
    }
    const Material& m = material_[static_cast<std::size_t>(i)];
    const std::string problem = material_error(normal_, tangential_, m);
    if (!problem.empty()) fail("type " + std::to_string(i) + ": " + problem);
  }
  mix_pairs();
  if (keeps_history(tangential_)) init_history();
  inertia_factor_ = inertia_ == 1 || (inertia_ == 0 && domain->dimension == 2) ? 0.5 : 0.4;
  init_rolling();
  double local = 0.0;
  for (int i = 0; i < atom->nlocal; ++i) local = std::max(local, atom->radius[i]);
  MPI_Allreduce(&local, &max_radius_, 1, MPI_DOUBLE, MPI_MAX, world);
  // and the grains a fix pour or deposit will insert during the run
  max_radius_ = std::max(max_radius_, inserted_radius_max());
  find_lightest();
  check_timestep();
  Pair::init_style(); // the default half list: j > i within the cutoff plus the skin
}

// Under pair_style hybrid each type pair has one sub-style. hybrid/overlay and hybrid/scaled add
// the forces of the sub-styles given the same pair: beside another granular style, a contact
// would be counted twice.
void PairGranthesis::check_hybrid() const {
  const std::string style = force->pair_style;
  if (style == "hybrid") return;
  for (const char* other :
       {"gran/hooke", "gran/hooke/history", "gran/hertz/history", "granular", "gran"})
    if (force->pair_match(other, 1) != nullptr)
      fail("pair_style " + style + " adds the forces of " + other +
           " and granthesis on the type pairs both are given, so that a contact would count "
           "twice; allowed: pair_style hybrid, which gives each type pair one contact law");
}

// Every type pair's parameters, mixed (talus/pair_parameters.hpp) or as pair_coeff I J gave
// them, wherever both types' materials or the pair's own are known: fix granthesis/wall needs a
// type's pairs also where pair_style hybrid gives that type's grain pairs to another sub-style.
void PairGranthesis::mix_pairs() {
  known_.assign(pair_.size(), 0);
  for (int i = 1; i <= ntypes_; ++i)
    for (int j = i; j <= ntypes_; ++j) {
      const std::size_t ij = slot(i, j);
      if (!explicit_pair_[ij]) {
        if (!given_[static_cast<std::size_t>(i)] || !given_[static_cast<std::size_t>(j)]) continue;
        pair_[ij] = mix(material_[static_cast<std::size_t>(i)],
                        material_[static_cast<std::size_t>(j)], impact_speed_);
      }
      pair_[slot(j, i)] = pair_[ij];
      known_[ij] = known_[slot(j, i)] = 1;
    }
}

// The lightest mass and smallest radius of each type's atoms now present (0 where none), over
// every rank: the collision times of the timestep check take them, as the native engine's
// automatic timestep does.
void PairGranthesis::find_lightest() {
  const auto n = static_cast<std::size_t>(ntypes_) + 1;
  std::vector<double> local(2 * n, HUGE_VAL);
  lightest_.assign(2 * n, HUGE_VAL);
  for (int i = 0; i < atom->nlocal; ++i) {
    const auto t = static_cast<std::size_t>(atom->type[i]);
    local[t] = std::min(local[t], atom->rmass[i]);
    local[n + t] = std::min(local[n + t], atom->radius[i]);
  }
  MPI_Allreduce(local.data(), lightest_.data(), static_cast<int>(2 * n), MPI_DOUBLE, MPI_MIN,
                world);
  for (double& x : lightest_)
    if (x == HUGE_VAL) x = 0.0;
}

double PairGranthesis::collision_time(const PairParameters& p, double m_eff, double r_eff) const {
  return with_normal_law(
      normal_, [&]<class N>() { return N::collision_time(p, m_eff, r_eff, impact_speed_); });
}

// The warning of a timestep too coarse for the stiffest pair of grains present: the lightest of
// either type, in a pair of two such grains (the bound is then conservative).
void PairGranthesis::check_timestep() const {
  double shortest = HUGE_VAL;
  int pi = 0, pj = 0;
  for (int i = 1; i <= ntypes_; ++i)
    for (int j = i; j <= ntypes_; ++j) {
      const double m = std::min(lightest_mass(i), lightest_mass(j));
      const double r = std::min(smallest_radius(i), smallest_radius(j));
      if (!has_parameters(i, j) || !(m > 0.0) || !(r > 0.0)) continue;
      const double tc = collision_time(parameters(i, j), 0.5 * m, 0.5 * r);
      if (tc < shortest) shortest = tc, pi = i, pj = j;
    }
  if (shortest == HUGE_VAL || comm->me != 0) return;
  const std::string problem =
      timestep_warning(shortest, update->dt,
                       "two grains of types " + std::to_string(pi) + " and " + std::to_string(pj));
  if (!problem.empty()) warn(error, std::string(style_name) + ": " + problem);
}

// A law with a spring keeps it per contact in fix granthesis/history. Each rank computes a
// contact with a ghost atom itself (newton_pair off) and keeps the spring of its own atom, so
// that no spring needs to be sent back to the rank that owns the ghost.
void PairGranthesis::init_history() {
  if (host_keeps_springs && force->newton_pair)
    fail("tangential law '" + std::string(name_of(tangential_)) +
         "' keeps a spring per contact, which needs newton_pair off (newton off before the box, "
         "or newton off on after it), so that each rank computes its own atoms' contacts");
  // a spring along the tangent in 2d, a vector in the tangent plane in 3d
  history_ =
      springs_fix(history_fix_id, history_slots_, style_name, domain->dimension == 3 ? 3 : 1);
}

// Rolling resistance keeps its springs as the tangential laws do, in a fix of its own.
bool PairGranthesis::rolling() const {
  for (int i = 1; i <= ntypes_; ++i)
    for (int j = i; j <= ntypes_; ++j) {
      const std::size_t ij = slot(i, j);
      // the pair as mix_pairs() will mix it (talus/pair_parameters.hpp), or as given
      const PairParameters p = explicit_pair_[ij] != 0
                                   ? pair_[ij]
                                   : mix(material_[static_cast<std::size_t>(i)],
                                         material_[static_cast<std::size_t>(j)], impact_speed_);
      if (p.rolling_friction > 0.0) return true;
    }
  return false;
}

void PairGranthesis::init_rolling() {
  rolling_ = rolling();
  if (!rolling_) return;
  if (host_keeps_springs && force->newton_pair)
    fail("rolling resistance (rolling_friction > 0) keeps a spring per contact, which needs "
         "newton_pair off (newton off before the box, or newton off on after it), so that each "
         "rank computes its own "
         "atoms' contacts");
  rolling_fix_ =
      springs_fix(rolling_fix_id, history_slots_, style_name, domain->dimension == 3 ? 3 : 1);
}

double PairGranthesis::rim_inertia(int i) const {
  const double r = atom->radius[i];
  return (inertia_factor_ + 1.0) * atom->rmass[i] * r * r;
}

template <class N>
double PairGranthesis::add_rolling_torque(int i, int j, const PairParameters& p,
                                          const ContactGeometry& g, double fn, bool advance) {
  if (p.rolling_friction == 0.0) return 0.0;
  double** omega = atom->omega;
  double** torque = atom->torque;
  const int nlocal = atom->nlocal;
  // each atom keeps the angle seen from itself: j's is the opposite of i's
  double& kept = rolling_fix_->spring(i, atom->tag[j]);
  double* mirror = j < nlocal ? &rolling_fix_->spring(j, atom->tag[i]) : nullptr;
  double theta = kept;
  const double m =
      RollingLaw::torque<N>(p, g, fn, omega[i][2] - omega[j][2],
                            rolling_inertia(rim_inertia(i), rim_inertia(j)), theta, update->dt);
  if (advance) {
    kept = theta;
    if (mirror) *mirror = -theta;
  }
  torque[i][2] += m;
  if (force->newton_pair || j < nlocal) torque[j][2] -= m;
  return RollingLaw::elastic_energy<N>(p, g, theta);
}

double PairGranthesis::init_one(int i, int j) {
  if (!has_parameters(i, j)) {
    const int missing = given_[static_cast<std::size_t>(i)] ? j : i;
    fail("types " + std::to_string(i) + " and " + std::to_string(j) +
         " are given to granthesis, "
         "but type " +
         std::to_string(missing) + " has no material (pair_coeff " + std::to_string(missing) + " " +
         std::to_string(missing) +
         " granthesis key value ...), nor the pair parameters of its own (pair_coeff " +
         std::to_string(i) + " " + std::to_string(j) + " granthesis key value ...)");
  }
  // The reach of a pair is the sum of the radii; the half list needs the largest (finitecutflag:
  // LAMMPS adds the skin)
  return 2.0 * std::max(max_radius_, 0.0);
}

void PairGranthesis::compute(int eflag, int vflag) {
  if (domain->dimension == 3) return compute_3d_pass(eflag, vflag);
  with_contact_law(normal_, tangential_,
                   [&]<class N, class T>() { compute_with<N, T>(eflag, vflag); });
}

template <class N, class T> void PairGranthesis::compute_with(int eflag, int vflag) {
  start_tally(eflag, vflag);
  double** x = atom->x;
  double** v = atom->v;
  double** f = atom->f;
  double** omega = atom->omega;
  double** torque = atom->torque;
  const double* radius = atom->radius;
  const double* rmass = atom->rmass;
  const int* type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const double dt = update->dt;
  [[maybe_unused]] const LAMMPS_NS::tagint* tag = atom->tag;
  // in the setup before a run the forces are computed again at the same state: the springs
  // keep their values (they advance once per step)
  [[maybe_unused]] const bool advance = update->setupflag == 0;
  if constexpr (T::has_history) history_->begin_pass();
  if (rolling_) rolling_fix_->begin_pass();
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii];
    const int* neighbours = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; ++jj) {
      const int j = neighbours[jj] & NEIGHMASK;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double reach = radius[i] + radius[j];
      const double dist2 = dx * dx + dy * dy;
      if (dist2 + dz * dz >= reach * reach || dist2 == 0.0) continue;
      if (dz != 0.0) [[unlikely]]
        out_of_plane(i, j, dz);
      // a law that does not use R* is spared its division
      const ContactGeometry g = pair_geometry(
          dx, dy, std::sqrt(dist2), radius[i], radius[j], rmass[i], rmass[j], v[i][0], v[i][1],
          v[j][0], v[j][1], omega[i][2], omega[j][2], N::uses_r_eff || T::uses_r_eff || rolling_);
      const PairParameters& p = parameters(type[i], type[j]);
      double history = 0.0;     // the spring: 0 for a law without one
      double* kept = nullptr;   // i's spring
      double* mirror = nullptr; // the same contact's spring kept by j, when j is this rank's
      if constexpr (T::has_history) {
        kept = &history_->spring(i, tag[j]);
        if (j < nlocal) mirror = &history_->spring(j, tag[i]);
        history = *kept;
      }
      const ContactForce c = contact_force<N, T>(p, g, history, dt);
      if constexpr (T::has_history)
        if (advance) {
          *kept = history;
          if (mirror) *mirror = history;
        }
      f[i][0] += c.force_x;
      f[i][1] += c.force_y;
      torque[i][2] += c.torque_i;
      if (newton_pair || j < nlocal) {
        f[j][0] -= c.force_x;
        f[j][1] -= c.force_y;
        torque[j][2] += c.torque_j;
      }
      const double rolling_energy =
          rolling_ ? add_rolling_torque<N>(i, j, p, g, not_below_zero(c.normal_force), advance)
                   : 0.0;
      if (evflag)
        ev_tally_xyz(i, j, nlocal, newton_pair,
                     eflag ? contact_elastic_energy<N, T>(p, g, history) + rolling_energy : 0.0,
                     0.0, c.force_x, c.force_y, 0.0, dx, dy, dz);
    }
  }
  if constexpr (T::has_history) history_->end_pass(nlocal);
  if (rolling_) rolling_fix_->end_pass(nlocal);
}

void PairGranthesis::out_of_plane(int i, int j, double dz) const {
  fail("atoms " + std::to_string(atom->tag[i]) + " and " + std::to_string(atom->tag[j]) +
       " touch out of the x-y plane (dz = " + std::to_string(dz) +
       " m): the thesis' laws are for disks, or spheres moving in a plane");
}

// The contact's elastic energy; fforce is F_n / r (LAMMPS multiplies by the separation vector to
// report the normal force); svector: the force on i (x, y), the torques on i and j, F_n and the
// overlap, all 0 for a pair that does not touch.
double PairGranthesis::single(int i, int j, int itype, int jtype, double rsq,
                              double /*factor_coul*/, double /*factor_lj*/, double& fforce) {
  std::fill(std::begin(svector_storage_), std::end(svector_storage_), 0.0);
  fforce = 0.0;
  if (domain->dimension == 3) return single_3d(i, j, itype, jtype, rsq, fforce);
  double** x = atom->x;
  double** v = atom->v;
  const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1];
  const double dist2 = dx * dx + dy * dy;
  const double reach = atom->radius[i] + atom->radius[j];
  if (rsq >= reach * reach || dist2 == 0.0) return 0.0;
  const ContactGeometry g = pair_geometry(
      dx, dy, std::sqrt(dist2), atom->radius[i], atom->radius[j], atom->rmass[i], atom->rmass[j],
      v[i][0], v[i][1], v[j][0], v[j][1], atom->omega[i][2], atom->omega[j][2]);
  const PairParameters& p = parameters(itype, jtype);
  double history = 0.0; // the spring as it stands (single changes nothing)
  if (history_) history = history_->peek(i, atom->tag[j]);
  return with_contact_law(normal_, tangential_, [&]<class N, class T>() {
    const ContactForce c = contact_force<N, T>(p, g, history, update->dt);
    fforce = c.normal_force / std::sqrt(rsq);
    svector_storage_[0] = c.force_x;
    svector_storage_[1] = c.force_y;
    svector_storage_[2] = c.torque_i;
    svector_storage_[3] = c.torque_j;
    svector_storage_[4] = c.normal_force;
    svector_storage_[5] = g.overlap;
    return contact_elastic_energy<N, T>(p, g, history);
  });
}

void PairGranthesis::write_restart_settings(FILE* file) {
  const int settings[5] = {restart_format, static_cast<int>(normal_), static_cast<int>(tangential_),
                           history_slots_, inertia_};
  std::fwrite(settings, sizeof(int), 5, file);
  std::fwrite(&impact_speed_, sizeof(double), 1, file);
}

void PairGranthesis::read_settings(FILE* file) {
  int settings[5] = {0, 0, 0, 0, 0};
  if (comm->me == 0) read_restart_items(lmp, settings, sizeof(int), 1, file);
  MPI_Bcast(settings, 1, MPI_INT, 0, world);
  if (settings[0] != restart_format)
    fail("the restart file was written by an older pair_style granthesis (before rolling "
         "resistance), whose materials this one cannot read; write it again with this version, "
         "or start from a data file");
  if (comm->me == 0) read_restart_items(lmp, settings + 1, sizeof(int), 4, file);
  MPI_Bcast(settings, 5, MPI_INT, 0, world);
  normal_ = static_cast<NormalLaw>(settings[1]);
  tangential_ = static_cast<TangentialLaw>(settings[2]);
  history_slots_ = settings[3]; // the restart file's springs must fit
  inertia_ = settings[4];
  if (comm->me == 0) read_restart_items(lmp, &impact_speed_, sizeof(double), 1, file);
  MPI_Bcast(&impact_speed_, 1, MPI_DOUBLE, 0, world);
}

// Per type pair (i <= j): whether it was set, whether it was given explicitly, then the material
// (i = j) or the pair parameters (i != j explicit), as doubles.
void PairGranthesis::write_restart(FILE* file) {
  write_restart_settings(file);
  for (int i = 1; i <= ntypes_; ++i)
    for (int j = i; j <= ntypes_; ++j) {
      const std::size_t ij = slot(i, j);
      const int flags[2] = {i == j ? given_[static_cast<std::size_t>(i)] : explicit_pair_[ij],
                            explicit_pair_[ij]};
      std::fwrite(flags, sizeof(int), 2, file);
      if (!flags[0]) continue;
      if (i == j) {
        const Material& m = material_[static_cast<std::size_t>(i)];
        for (const MaterialKey& k : material_keys)
          std::fwrite(&(m.*k.field), sizeof(double), 1, file);
      } else if (flags[1]) {
        std::fwrite(&pair_[ij], sizeof(PairParameters), 1, file);
      }
    }
}

void PairGranthesis::read_coefficients(FILE* file) {
  read_settings(file);
  allocate();
  for (int i = 1; i <= ntypes_; ++i)
    for (int j = i; j <= ntypes_; ++j) {
      const std::size_t ij = slot(i, j);
      int flags[2] = {0, 0};
      if (comm->me == 0) read_restart_items(lmp, flags, sizeof(int), 2, file);
      MPI_Bcast(flags, 2, MPI_INT, 0, world);
      if (i == j) given_[static_cast<std::size_t>(i)] = static_cast<char>(flags[0]);
      explicit_pair_[ij] = static_cast<char>(flags[1]);
      if (!flags[0]) continue;
      if (i == j) {
        Material& m = material_[static_cast<std::size_t>(i)];
        for (const MaterialKey& k : material_keys) {
          double value = 0.0;
          if (comm->me == 0) read_restart_items(lmp, &value, sizeof(double), 1, file);
          MPI_Bcast(&value, 1, MPI_DOUBLE, 0, world);
          m.*k.field = value;
        }
      } else if (flags[1]) {
        if (comm->me == 0) read_restart_items(lmp, &pair_[ij], sizeof(PairParameters), 1, file);
        MPI_Bcast(&pair_[ij], sizeof(PairParameters), MPI_BYTE, 0, world);
      }
    }
}

} // namespace talus::lammps
