// fix granthesis/wall in 3d: plates (whole planes or rectangles), fixed or driven, touched by
// spheres at the plate's point nearest their centre, from either side. Where a sphere touches a
// plate and how a plate moves are the native engine's lines (src/talus/plate.hpp), the force is
// the shared kernel's 3D contact (contact_force.hpp); the 2d segments are
// fix_granthesis_wall.cpp's.
#include <cmath>
#include <string>

#include "atom.h"
#include "fix_contact_history.h"
#include "fix_granthesis_wall.h"
#include "pair_granthesis.h"
#include "talus/contact_force.hpp"
#include "talus/rolling_resistance.hpp"
#include "update.h"

namespace talus::lammps {

using wall_words::usage;

namespace {

Vec3 vec(const double* a) {
  return {a[0], a[1], a[2]};
}
void store(double* to, const Vec3& a) {
  to[0] = a.x, to[1] = a.y, to[2] = a.z;
}

} // namespace

Vec3 FixGranthesisWall::vector(int narg, char** arg, int k, const char* what) const {
  const std::string name = what;
  return {number(narg, arg, k, (name + "X").c_str()),
          number(narg, arg, k + 1, (name + "Y").c_str()),
          number(narg, arg, k + 2, (name + "Z").c_str())};
}

// The plate at arg[k] ("plane PX PY PZ NX NY NZ type T [extent HALF_U HALF_V]"): through P,
// facing N (either side touches); whole, or a rectangle of those half-widths along the axes
// make_plane chooses. Returns the index past it.
int FixGranthesisWall::read_plate(int narg, char** arg, int k) {
  const std::string which = "plane " + std::to_string(plates_.size() + 1);
  const Vec3 point = vector(narg, arg, k + 1, "P");
  const Vec3 normal = vector(narg, arg, k + 4, "N");
  if (!(magnitude(normal) > 0.0))
    fail(which + ": normal NX NY NZ = 0 0 0; allowed: a direction, not zero");
  const int type = read_type(narg, arg, k + 7, which);
  k += 9;
  double half_u = unbounded, half_v = unbounded;
  if (k < narg && std::string(arg[k]) == "extent") {
    half_u = number(narg, arg, k + 1, "HALF_U"), half_v = number(narg, arg, k + 2, "HALF_V");
    if (!(half_u > 0.0 && half_v > 0.0))
      fail(which + ": extent " + arg[k + 1] + " " + arg[k + 2] +
           "; allowed: both half-widths > 0 (m)");
    k += 3;
  }
  const Plane plane = make_plane(point, normal, half_u, half_v);
  plates_.push_back({{plane.centre, plane.normal, plane.axis_u}, plane, std::nullopt, type});
  return k;
}

// The motion keyword at arg[k] for the last plate, as the native plate drivers take it; returns
// the index past its values.
int FixGranthesisWall::read_plate_motion(int narg, char** arg, int k) {
  const std::string key = arg[k];
  if (plates_.empty()) fail(key + " before any plane (" + usage + ")");
  PlateWall& w = plates_.back();
  const std::string which = "plane " + std::to_string(plates_.size());
  if (w.driver)
    fail(which + " is given a second motion (" + key + "); allowed: one motion per plane");
  PlateDriver d;
  d.plate = static_cast<std::uint32_t>(plates_.size() - 1);
  if (key == "velocity") {
    d.motion = PlateDriver::Motion::translate;
    d.velocity = vector(narg, arg, k + 1, "V");
    w.driver = d;
    return k + 4;
  }
  if (key == "rotate") {
    d.motion = PlateDriver::Motion::rotate;
    d.pivot = vector(narg, arg, k + 1, "P");
    d.angular_velocity = vector(narg, arg, k + 4, "W");
    w.driver = d;
    return k + 7;
  }
  d.motion = PlateDriver::Motion::vibrate;
  d.direction = vector(narg, arg, k + 1, "D");
  if (!(magnitude(d.direction) > 0.0))
    fail(which + ": vibrate DX DY DZ = 0 0 0; allowed: a direction, not zero");
  k = read_vibration(narg, arg, k + 4, which, d.amplitude, d.frequency, d.phase);
  w.driver = d;
  return k;
}

// Every driven plate where its motion has it t seconds after the fix's start.
void FixGranthesisWall::place_plates(double t) {
  for (PlateWall& w : plates_)
    if (w.driver) place_plate(w.now, *w.driver, w.start, t);
}

// Atom i's contact with plate s at its nearest point `touch`, the plate's velocity there.
ContactGeometry3 FixGranthesisWall::plate_geometry(int i, std::size_t s, const Vec3& touch) const {
  const Vec3 d = vec(atom->x[i]) - touch;
  return wall_geometry(d, std::sqrt(dot(d, d)), atom->radius[i], atom->rmass[i], vec(atom->v[i]),
                       vec(atom->omega[i]), plates_[s].now.velocity_at(touch));
}

// Every plate against every atom of the group: plates are few (a box has six), so there is no
// list of the plates near each atom, and the forces are summed in plate order.
template <class N, class T> void FixGranthesisWall::add_plate_forces(bool advance) {
  double** f = atom->f;
  double** torque = atom->torque;
  const int* mask = atom->mask;
  const double dt = update->dt;
  double power = 0.0;
  if constexpr (T::has_history) history_->begin_pass();
  if (rolling_) rolling_->begin_pass();
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    const Vec3 x = vec(atom->x[i]);
    const double r = atom->radius[i];
    for (std::size_t s = 0; s < plates_.size(); ++s) {
      const Plane& plate = plates_[s].now;
      const Vec3 touch = closest_point(plate, x);
      const Vec3 d = x - touch;
      const double dist2 = dot(d, d);
      if (dist2 >= r * r || dist2 == 0.0) continue;
      contacts_[static_cast<std::size_t>(i)] += 1.0;
      const ContactGeometry3 g = plate_geometry(i, s, touch);
      if (!pair_->has_parameters(atom->type[i], plates_[s].type)) [[unlikely]]
        unknown_pair(i, s);
      const PairParameters& p = pair_->parameters(atom->type[i], plates_[s].type);
      Vec3 spring{};
      double* kept = nullptr;
      if constexpr (T::has_history) {
        kept = history_->springs(i, static_cast<LAMMPS_NS::tagint>(s + 1));
        spring = vec(kept);
      }
      const ContactForce3 c = contact_force<N, T>(p, g, spring, dt);
      if constexpr (T::has_history)
        if (advance) store(kept, spring);
      for (int k = 0; k < 3; ++k) f[i][k] += (&c.force.x)[k];
      const Vec3 turned = vec(torque[i]) + c.torque_i;
      store(torque[i], turned);
      force_[0] -= c.force.x, force_[1] -= c.force.y, force_[2] -= c.force.z;
      power += dot(c.force, plate.velocity_at(touch));
      energy_ += contact_elastic_energy<N, T>(p, g, spring);
      if (rolling_)
        energy_ +=
            add_plate_rolling_torque<N>(i, s, p, g, not_below_zero(c.normal_force), advance, power);
      local_.insert(local_.end(), {static_cast<double>(atom->tag[i]), static_cast<double>(s + 1),
                                   c.normal_force, g.overlap, touch.x, touch.y, touch.z});
      local_atom_.push_back(i);
    }
  }
  if constexpr (T::has_history) history_->end_pass(atom->nlocal);
  if (rolling_) rolling_->end_pass(atom->nlocal);
  if (advance) work_ += power * dt;
}

// Rolling resistance between atom i and plate s, the plate's spin that of its turn: adds the
// torque to the atom and its work to `power`, returns the rolling spring's elastic energy.
template <class N>
double FixGranthesisWall::add_plate_rolling_torque(int i, std::size_t s, const PairParameters& p,
                                                   const ContactGeometry3& g, double fn,
                                                   bool advance, double& power) {
  if (p.rolling_friction == 0.0) return 0.0;
  const Vec3 spin = plates_[s].now.angular_velocity;
  double* kept = rolling_->springs(i, static_cast<LAMMPS_NS::tagint>(s + 1));
  Vec3 theta = into_tangent_plane(vec(kept), g.normal);
  const Vec3 m = RollingLaw::torque<N>(p, g, fn, rolling_spin(vec(atom->omega[i]), spin, g.normal),
                                       rolling_inertia(pair_->rim_inertia(i)), theta, update->dt);
  if (advance) store(kept, theta);
  store(atom->torque[i], vec(atom->torque[i]) + m);
  power += dot(m, spin); // the turning plate's work through the torque
  return RollingLaw::elastic_energy<N>(p, g, theta);
}

// The local array's normal forces again from the step's final velocities (see end_of_step).
template <class N, class T> void FixGranthesisWall::refresh_plate_normal_forces() {
  for (std::size_t k = 0; k < local_atom_.size(); ++k) {
    double* row = &local_[k * static_cast<std::size_t>(columns_)];
    const int i = local_atom_[k];
    const auto s = static_cast<std::size_t>(row[1]) - 1;
    const ContactGeometry3 g = plate_geometry(i, s, {row[4], row[5], row[6]});
    Vec3 spring{}; // the normal force does not depend on it
    row[2] = contact_force<N, T>(pair_->parameters(atom->type[i], plates_[s].type), g, spring,
                                 update->dt)
                 .normal_force;
  }
}

// The passes post_force() and end_of_step() call in 3d, for the run's law pair: every law pair
// is instantiated here, where the templates are defined.
void FixGranthesisWall::plate_pass(bool advance) {
  with_contact_law(pair_->normal_law(), pair_->tangential_law(),
                   [&]<class N, class T>() { add_plate_forces<N, T>(advance); });
}

void FixGranthesisWall::refresh_plate_pass() {
  with_contact_law(pair_->normal_law(), pair_->tangential_law(),
                   [&]<class N, class T>() { refresh_plate_normal_forces<N, T>(); });
}

} // namespace talus::lammps
