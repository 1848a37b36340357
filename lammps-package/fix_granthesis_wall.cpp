#include "fix_granthesis_wall.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include <mpi.h>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_contact_history.h"
#include "force.h"
#include "host_api.hpp"
#include "modify.h"
#include "neighbor.h"
#include "pair_coefficients.hpp"
#include "pair_granthesis.h"
#include "talus/contact_force.hpp"
#include "talus/rolling_resistance.hpp"
#include "talus/vibration.hpp"
#include "timestep_check.hpp"
#include "update.h"

namespace talus::lammps {

using wall_words::style_name;
using wall_words::usage;

FixGranthesisWall::FixGranthesisWall(LAMMPS_NS::LAMMPS* instance, int narg, char** arg)
    : Fix(instance, narg, arg) {
  scalar_flag = 1;
  vector_flag = 1;
  global_freq = 1;
  extscalar = 1;
  extvector = 1;
  energy_global_flag = 1; // fix_modify ID energy yes: the walls' elastic energy joins pe
  restart_global = 1;     // the walls' clock and work
  // per atom: how many walls it touches (compute contact/atom does not see the walls)
  peratom_flag = 1;
  size_peratom_cols = 0;
  peratom_freq = 1;
  // local: a row per wall contact (dump local), as the native engine's contacts.vtp has them
  local_flag = 1;
  local_freq = 1;
  three_d_ = domain->dimension == 3;
  size_vector = three_d_ ? 4 : 3;
  columns_ = three_d_ ? 7 : 6;
  size_local_cols = columns_;
  const std::string wall = wall_word();
  for (int k = 3; k < narg;) {
    const std::string key = arg[k];
    if (key == "segment" || key == "plane") {
      if (key != wall)
        fail(
            key + ": " +
            (three_d_ ? "a segment is a wall of dimension 2" : "a plane is a wall of dimension 3") +
            "; allowed in this dimension: " + wall + " (" + usage + ")");
      k = three_d_ ? read_plate(narg, arg, k) : read_segment(narg, arg, k);
    } else if (key == "velocity" || key == "rotate" || key == "vibrate") {
      k = three_d_ ? read_plate_motion(narg, arg, k) : read_motion(narg, arg, k);
    } else {
      fail("unknown keyword '" + key + "'; allowed: " + wall + ", velocity, rotate, vibrate (" +
           usage + ")");
    }
  }
  if (wall_count() == 0) fail("no " + wall + " given (" + usage + ")");
  placed_.resize(walls_.size());
  hits_.resize(walls_.size());
  start_ = now();
  place(0.0);
  place_plates(0.0);
}

// The segment at arg[k] ("segment AX AY BX BY type T"); returns the index past it.
int FixGranthesisWall::read_segment(int narg, char** arg, int k) {
  Wall w{number(narg, arg, k + 1, "AX"), number(narg, arg, k + 2, "AY"),
         number(narg, arg, k + 3, "BX"), number(narg, arg, k + 4, "BY"), 0};
  w.type = read_type(narg, arg, k + 5, "segment " + std::to_string(walls_.size() + 1));
  walls_.push_back(w);
  return k + 7;
}

// "type T" at arg[k], after the wall `which`'s geometry.
int FixGranthesisWall::read_type(int narg, char** arg, int k, const std::string& which) const {
  if (k >= narg || std::string(arg[k]) != "type")
    fail(which + ": 'type T' must follow its " + (three_d_ ? "point and normal" : "end points") +
         " (" + usage + ")");
  const double t = number(narg, arg, k + 1, "T");
  if (t < 1.0 || t != std::floor(t))
    fail("type = " + std::string(arg[k + 1]) + "; allowed: an atom type, 1 or more");
  return static_cast<int>(t);
}

double FixGranthesisWall::number(int narg, char** arg, int k, const char* what) const {
  if (k >= narg) fail(std::string(what) + " is missing (" + usage + ")");
  const std::optional<double> x = finite_number(arg[k]);
  if (!x) fail(std::string(what) + " = " + arg[k] + "; allowed: a finite number");
  return *x;
}

// The motion keyword at arg[k] for the last segment; returns the index past its values.
int FixGranthesisWall::read_motion(int narg, char** arg, int k) {
  const std::string key = arg[k];
  if (walls_.empty()) fail(key + " before any segment (" + usage + ")");
  Wall& w = walls_.back();
  const std::string which = "segment " + std::to_string(walls_.size());
  if (w.motion != Motion::none)
    fail(which + " is given a second motion (" + key + "); allowed: one motion per segment");
  if (key == "velocity") {
    w.motion = Motion::translate;
    w.vx = number(narg, arg, k + 1, "VX"), w.vy = number(narg, arg, k + 2, "VY");
    return k + 3;
  }
  if (key == "rotate") {
    w.motion = Motion::rotate;
    w.cx = number(narg, arg, k + 1, "CX"), w.cy = number(narg, arg, k + 2, "CY");
    w.omega = number(narg, arg, k + 3, "OMEGA");
    return k + 4;
  }
  w.motion = Motion::vibrate;
  const double dx = number(narg, arg, k + 1, "DX"), dy = number(narg, arg, k + 2, "DY");
  const double length = std::sqrt(dx * dx + dy * dy);
  if (!(length > 0.0)) fail(which + ": vibrate DX DY = 0 0; allowed: a direction, not zero");
  w.dx = dx / length, w.dy = dy / length; // as the native driver normalises it
  return read_vibration(narg, arg, k + 3, which, w.amplitude, w.frequency, w.phase);
}

// A vibration's "AMPLITUDE FREQUENCY PHASE" at arg[k], of the wall `which`; returns the index
// past them.
int FixGranthesisWall::read_vibration(int narg, char** arg, int k, const std::string& which,
                                      double& amplitude, double& frequency, double& phase) const {
  amplitude = number(narg, arg, k, "AMPLITUDE");
  frequency = number(narg, arg, k + 1, "FREQUENCY");
  phase = number(narg, arg, k + 2, "PHASE");
  if (amplitude < 0.0 || frequency < 0.0)
    fail(which + ": vibrate AMPLITUDE " + arg[k] + " FREQUENCY " + arg[k + 1] +
         "; allowed: both >= 0 (m, Hz)");
  return k + 3;
}

FixGranthesisWall::~FixGranthesisWall() {
  if (history_ && modify->find_fix(history_id_) >= 0) modify->delete_fix(history_id_);
  if (rolling_ && modify->find_fix(rolling_id_) >= 0) modify->delete_fix(rolling_id_);
}

void FixGranthesisWall::fail(const std::string& message, std::source_location at) const {
  talus::lammps::fail(error, style_name, message, at);
}

int FixGranthesisWall::setmask() {
  return LAMMPS_NS::FixConst::POST_FORCE | LAMMPS_NS::FixConst::END_OF_STEP;
}

double FixGranthesisWall::now() const {
  return clock_.now(*update);
}

void FixGranthesisWall::init() {
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    fail("needs per-atom radius, mass, angular velocity and torque: atom_style sphere");
  if ((domain->dimension == 3) != three_d_)
    fail("the walls were defined in dimension " + std::string(three_d_ ? "3" : "2") +
         ", and this run has dimension " + std::to_string(domain->dimension) +
         "; allowed: the dimension the fix was defined in");
  pair_ = dynamic_cast<PairGranthesis*>(force->pair_match("granthesis", 1));
  if (!pair_)
    fail("needs pair_style granthesis: the walls take its laws and the materials of its types");
  for (std::size_t s = 0; s < wall_count(); ++s)
    if (wall_type(s) > atom->ntypes)
      fail(std::string(wall_word()) + " " + std::to_string(s + 1) + ": type " +
           std::to_string(wall_type(s)) + " does not exist; allowed: 1 to " +
           std::to_string(atom->ntypes));
  history_ = rolling_ = nullptr;
  make_history();
  check_timestep();
}

// The warning of a timestep too coarse for the stiffest wall contact: the lightest and smallest
// grain of each type present against each wall's type (a wall does not move back).
void FixGranthesisWall::check_timestep() const {
  double shortest = HUGE_VAL;
  int grain = 0, wall = 0;
  for (int t = 1; t <= atom->ntypes; ++t)
    for (std::size_t s = 0; s < wall_count(); ++s) {
      const int w = wall_type(s);
      const double m = pair_->lightest_mass(t), r = pair_->smallest_radius(t);
      if (!pair_->has_parameters(t, w) || !(m > 0.0) || !(r > 0.0)) continue;
      const double tc = pair_->collision_time(pair_->parameters(t, w), m, r);
      if (tc < shortest) shortest = tc, grain = t, wall = w;
    }
  if (shortest == HUGE_VAL || comm->me != 0) return;
  const std::string problem =
      timestep_warning(shortest, update->dt,
                       "a grain of type " + std::to_string(grain) + " with a " + wall_word() +
                           " of type " + std::to_string(wall));
  if (!problem.empty()) warn(error, std::string(style_name) + ": " + problem);
}

// A grain touching a wall whose type pair has no parameters: under pair_style hybrid, a type
// given to another sub-style still needs a granthesis material for the walls.
void FixGranthesisWall::unknown_pair(int i, std::size_t s) const {
  const int t = atom->type[i], w = wall_type(s);
  const int missing = pair_->has_parameters(t, t) ? w : t;
  const std::string m = std::to_string(missing);
  fail("atom " + std::to_string(atom->tag[i]) + " of type " + std::to_string(t) + " touches " +
       wall_word() + " " + std::to_string(s + 1) + " of type " + std::to_string(w) + ", but type " +
       m +
       " has no granthesis material: the walls apply granthesis' laws to every atom of the "
       "group, also where pair_style hybrid gives a type's grain pairs to another sub-style; "
       "allowed: give every type a granthesis material before handing its pairs on (pair_coeff "
       "* * granthesis key value ..., then pair_coeff " +
       m + " " + m + " OTHER_STYLE ...)");
}

// The springs of the wall contacts, per atom and wall (numbered from 1): the tangential law's,
// and the rolling resistance's where a pair has some; a number each in 2d, a vector in 3d.
void FixGranthesisWall::make_history() {
  const int values = three_d_ ? 3 : 1;
  if (keeps_history(pair_->tangential_law())) {
    history_id_ = std::string(id) + "_HISTORY";
    history_ = FixContactHistory::find_or_make(lmp, history_id_, pair_->history_slots(), style_name,
                                               values);
  }
  if (host_keeps_springs && pair_->rolling()) { // else the pair style stops the run
    rolling_id_ = std::string(id) + "_ROLLING";
    rolling_ = FixContactHistory::find_or_make(lmp, rolling_id_, pair_->history_slots(), style_name,
                                               values);
  }
}

// Where the pair style is known already (always after read_restart, which brings it back), the
// springs' fix is made now, not at init(): only a fix made before the first run after
// read_restart gets its atoms' values from the restart file.
void FixGranthesisWall::post_constructor() {
  pair_ = dynamic_cast<PairGranthesis*>(force->pair_match("granthesis", 1));
  if (pair_) make_history();
}

void FixGranthesisWall::setup(int vflag) {
  clock_.setup(*update);
  post_force(vflag);
}

// Where the walls are t seconds after the start, and their translation's velocity: moved along,
// turned about their centre, or vibrating along their direction.
void FixGranthesisWall::place(double t) {
  for (std::size_t s = 0; s < walls_.size(); ++s) {
    const Wall& w = walls_[s];
    Placed& p = placed_[s];
    if (w.motion == Motion::rotate) {
      const double c = std::cos(w.omega * t), sn = std::sin(w.omega * t);
      const auto turn = [&](double x, double y, double& ox, double& oy) {
        ox = w.cx + c * (x - w.cx) - sn * (y - w.cy);
        oy = w.cy + sn * (x - w.cx) + c * (y - w.cy);
      };
      turn(w.ax, w.ay, p.ax, p.ay);
      turn(w.bx, w.by, p.bx, p.by);
      p.vx = p.vy = 0.0;
      continue;
    }
    double ox = w.vx * t, oy = w.vy * t; // no motion: velocity 0
    p.vx = w.vx, p.vy = w.vy;
    if (w.motion == Motion::vibrate) {
      const VibrationState v = vibration_at(w.amplitude, w.frequency, w.phase, t);
      ox = v.displacement * w.dx, oy = v.displacement * w.dy;
      p.vx = v.velocity * w.dx, p.vy = v.velocity * w.dy;
    }
    p.ax = w.ax + ox, p.ay = w.ay + oy, p.bx = w.bx + ox, p.by = w.by + oy;
  }
}

void FixGranthesisWall::post_force(int /*vflag*/) {
  // in the setup before a run the forces are computed again at the same state: the springs and
  // the work keep their values
  const bool advance = update->setupflag == 0;
  begin_local();
  if (three_d_) {
    place_plates(now() - start_);
    plate_pass(advance);
  } else {
    place(now() - start_);
    with_contact_law(pair_->normal_law(), pair_->tangential_law(),
                     [&]<class N, class T>() { add_forces<N, T>(advance); });
  }
  publish_local();
}

// A step's outputs start empty: the local array's rows, the per-atom counts, the energy and
// the force on the walls.
void FixGranthesisWall::begin_local() {
  energy_ = 0.0;
  force_[0] = force_[1] = force_[2] = 0.0;
  // read only after this step's forces (thermo, dumps), so it need not move with the atoms
  contacts_.assign(static_cast<std::size_t>(std::max(atom->nmax, 1)), 0.0);
  vector_atom = contacts_.data();
  local_.clear();
  local_atom_.clear();
}

template <class N, class T> void FixGranthesisWall::add_forces(bool advance) {
  double** x = atom->x;
  double** f = atom->f;
  double** torque = atom->torque;
  const int* mask = atom->mask;
  const int* type = atom->type;
  const double dt = update->dt;
  double power = 0.0;
  if constexpr (T::has_history) history_->begin_pass();
  if (rolling_) rolling_->begin_pass();
  // the rows of segments near each atom: again after LAMMPS' own lists (the atoms may have
  // changed ranks or order), or when the atoms and segments may have moved past them
  if (update->setupflag || neighbor->ago == 0 ||
      near_.stale(x, mask, groupbit, atom->nlocal, placed_))
    near_.build(x, atom->radius, mask, groupbit, atom->nlocal, placed_, neighbor->skin);
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    const double r = atom->radius[i];
    const int* row = near_.begin(i);
    const auto count = static_cast<std::size_t>(near_.end(i) - row);
    for (std::size_t m = 0; m < count; ++m) {
      const Placed& w = placed_[static_cast<std::size_t>(row[m])];
      hits_[m] = segment_hit(w.ax, w.ay, w.bx, w.by, x[i][0], x[i][1], r);
    }
    const auto shares = [&](std::size_t m, double px, double py) {
      const Placed& o = placed_[static_cast<std::size_t>(row[m])];
      return (o.ax == px && o.ay == py) || (o.bx == px && o.by == py);
    };
    for (std::size_t m = 0; m < count; ++m) {
      const SegmentHit& h = hits_[m];
      if (!h.touching || (h.vertex() && duplicate_vertex(hits_, count, m, shares))) continue;
      const auto s = static_cast<std::size_t>(row[m]);
      contacts_[static_cast<std::size_t>(i)] += 1.0;
      double wx = 0.0, wy = 0.0;
      const ContactGeometry g = geometry(i, s, h.x, h.y, wx, wy);
      if (!pair_->has_parameters(type[i], walls_[s].type)) [[unlikely]]
        unknown_pair(i, s);
      const PairParameters& p = pair_->parameters(type[i], walls_[s].type);
      double spring = 0.0;
      double* kept = nullptr;
      if constexpr (T::has_history) {
        kept = &history_->spring(i, static_cast<LAMMPS_NS::tagint>(s + 1));
        spring = *kept;
      }
      const ContactForce c = contact_force<N, T>(p, g, spring, dt);
      if constexpr (T::has_history)
        if (advance) *kept = spring;
      f[i][0] += c.force_x;
      f[i][1] += c.force_y;
      torque[i][2] += c.torque_i;
      force_[0] -= c.force_x;
      force_[1] -= c.force_y;
      power += c.force_x * wx + c.force_y * wy;
      energy_ += contact_elastic_energy<N, T>(p, g, spring);
      if (rolling_ && p.rolling_friction > 0.0) {
        double& theta = rolling_->spring(i, static_cast<LAMMPS_NS::tagint>(s + 1));
        double turned = theta;
        const double moment = RollingLaw::torque<N>(
            p, g, not_below_zero(c.normal_force), atom->omega[i][2] - walls_[s].omega,
            rolling_inertia(pair_->rim_inertia(i)), turned, dt);
        if (advance) theta = turned;
        torque[i][2] += moment;
        power += moment * walls_[s].omega; // the turning wall's work through the torque
        energy_ += RollingLaw::elastic_energy<N>(p, g, turned);
      }
      local_.insert(local_.end(), {static_cast<double>(atom->tag[i]), static_cast<double>(s + 1),
                                   c.normal_force, g.overlap, h.x, h.y});
      local_atom_.push_back(i);
    }
  }
  if constexpr (T::has_history) history_->end_pass(atom->nlocal);
  if (rolling_) rolling_->end_pass(atom->nlocal);
  if (advance) work_ += power * dt;
}

// Atom i's contact with segment s at the point (hx, hy): its geometry, and the wall's velocity
// there (its translation or vibration, or its turn about the centre).
ContactGeometry FixGranthesisWall::geometry(int i, std::size_t s, double hx, double hy, double& wx,
                                            double& wy) const {
  const Wall& w = walls_[s];
  const Placed& at = placed_[s];
  wx = at.vx - w.omega * (hy - w.cy), wy = at.vy + w.omega * (hx - w.cx);
  const double* x = atom->x[i];
  const double dx = x[0] - hx, dy = x[1] - hy;
  return wall_geometry(dx, dy, std::sqrt(dx * dx + dy * dy), atom->radius[i], atom->rmass[i],
                       atom->v[i][0], atom->v[i][1], atom->omega[i][2], wx, wy);
}

// The local array's normal forces again from the step's final velocities: the state a dump
// shows, as compute pair/local gives the pairs' (the positions, so the overlaps and points, are
// those of the force stage).
void FixGranthesisWall::end_of_step() {
  if (three_d_) return refresh_plate_pass();
  with_contact_law(pair_->normal_law(), pair_->tangential_law(),
                   [&]<class N, class T>() { refresh_normal_forces<N, T>(); });
}

template <class N, class T> void FixGranthesisWall::refresh_normal_forces() {
  for (std::size_t k = 0; k < local_atom_.size(); ++k) {
    double* row = &local_[k * static_cast<std::size_t>(columns_)];
    const int i = local_atom_[k];
    const auto s = static_cast<std::size_t>(row[1]) - 1;
    double wx = 0.0, wy = 0.0;
    const ContactGeometry g = geometry(i, s, row[4], row[5], wx, wy);
    double spring = 0.0; // the normal force does not depend on it
    row[2] =
        contact_force<N, T>(pair_->parameters(atom->type[i], walls_[s].type), g, spring, update->dt)
            .normal_force;
  }
}

// The local array: a row per wall contact of this rank's atoms in the last step.
void FixGranthesisWall::publish_local() {
  const auto columns = static_cast<std::size_t>(columns_);
  const std::size_t rows = local_.size() / columns;
  local_rows_.resize(rows);
  for (std::size_t k = 0; k < rows; ++k) local_rows_[k] = &local_[k * columns];
  size_local_rows = static_cast<int>(rows);
  array_local = local_rows_.data();
}

// The walls' elastic energy, over every rank's atoms (with fix_modify energy yes, part of pe).
double FixGranthesisWall::compute_scalar() {
  double total = 0.0;
  MPI_Allreduce(&energy_, &total, 1, MPI_DOUBLE, MPI_SUM, world);
  return total;
}

// 1: the work the walls have done on the atoms so far (J); 2, 3 (and 4 in 3d): the force of the
// atoms on the walls in the last step (N).
double FixGranthesisWall::compute_vector(int n) {
  if (summed_step_ != update->ntimestep) {
    const double local[4] = {work_, force_[0], force_[1], force_[2]};
    MPI_Allreduce(local, totals_, size_vector, MPI_DOUBLE, MPI_SUM, world);
    summed_step_ = update->ntimestep;
  }
  return totals_[n];
}

// The time, the walls' start, the work they have done (over every rank's atoms) and their count:
// the fix defined again under the same ID after read_restart takes up the motion where it was,
// rather than from the deck's end points.
void FixGranthesisWall::write_restart(FILE* file) {
  double work = 0.0;
  MPI_Allreduce(&work_, &work, 1, MPI_DOUBLE, MPI_SUM, world);
  if (comm->me != 0) return;
  const double state[4] = {now(), start_, work, static_cast<double>(wall_count())};
  write_fix_state(file, state, 4);
}

void FixGranthesisWall::restart(char* buffer) {
  double state[4];
  std::memcpy(state, buffer, sizeof state);
  if (state[3] != static_cast<double>(wall_count()))
    fail("fix " + std::string(id) + " had " + std::to_string(static_cast<long>(state[3])) + " " +
         wall_word() + "(s) in the run that wrote the restart file, " +
         std::to_string(wall_count()) + " now; allowed: the " + wall_word() +
         "s of that run, as its deck gave them");
  clock_.resume(state[0]);
  start_ = state[1];
  work_ = comm->me == 0 ? state[2] : 0.0; // the total, kept by one rank
  place(now() - start_);
  place_plates(now() - start_);
}

} // namespace talus::lammps
