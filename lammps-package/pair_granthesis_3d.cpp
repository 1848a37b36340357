// pair_style granthesis for spheres in 3D (dimension 3): the contact laws of src/talus on
// vectors (talus/contact_geometry_3d.hpp), the springs and rolling angles kept as vectors in
// fix granthesis/history (three numbers per contact) and turned into each contact's tangent
// plane as it turns. The 2D pass is pair_granthesis.cpp's.
#include <cmath>

#include "atom.h"
#include "force.h"
#include "neigh_list.h"
#include "pair_granthesis.h"
#include "talus/contact_force.hpp"
#include "talus/rolling_resistance.hpp"
#include "update.h"

namespace talus::lammps {

namespace {

Vec3 vec(const double* a) {
  return {a[0], a[1], a[2]};
}
void store(double* to, const Vec3& a) {
  to[0] = a.x, to[1] = a.y, to[2] = a.z;
}
void add(double* to, const Vec3& a) {
  to[0] += a.x, to[1] += a.y, to[2] += a.z;
}

} // namespace

// Each atom keeps the springs and angles seen from itself: from j's side the contact point's
// slip is the opposite of i's, so j keeps -s (2D's scalar along t keeps its sign, t turning
// with n).
template <class N, class T> void PairGranthesis::compute_3d(int eflag, int vflag) {
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
  // in the setup before a run the forces are computed again at the same state
  [[maybe_unused]] const bool advance = update->setupflag == 0;
  if constexpr (T::has_history) history_->begin_pass();
  if (rolling_) rolling_fix_->begin_pass();
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii];
    const int* neighbours = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; ++jj) {
      const int j = neighbours[jj] & NEIGHMASK;
      const Vec3 d{x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double reach = radius[i] + radius[j];
      const double dist2 = dot(d, d);
      if (dist2 >= reach * reach || dist2 == 0.0) continue;
      const ContactGeometry3 g = pair_geometry(
          d, std::sqrt(dist2), radius[i], radius[j], rmass[i], rmass[j], vec(v[i]), vec(v[j]),
          vec(omega[i]), vec(omega[j]), N::uses_r_eff || T::uses_r_eff || rolling_);
      const PairParameters& p = parameters(type[i], type[j]);
      Vec3 history{}; // the spring: none for a law without one
      double* kept = nullptr;
      double* mirror = nullptr;
      if constexpr (T::has_history) {
        kept = history_->springs(i, tag[j]);
        if (j < nlocal) mirror = history_->springs(j, tag[i]);
        history = vec(kept);
      }
      const ContactForce3 c = contact_force<N, T>(p, g, history, dt);
      if constexpr (T::has_history)
        if (advance) {
          store(kept, history);
          if (mirror) store(mirror, -history);
        }
      add(f[i], c.force);
      add(torque[i], c.torque_i);
      if (newton_pair || j < nlocal) {
        add(f[j], -c.force);
        add(torque[j], c.torque_j);
      }
      const double rolling_energy =
          rolling_ ? add_rolling_torque_3d<N>(i, j, p, g, not_below_zero(c.normal_force), advance)
                   : 0.0;
      if (evflag)
        ev_tally_xyz(i, j, nlocal, newton_pair,
                     eflag ? contact_elastic_energy<N, T>(p, g, history) + rolling_energy : 0.0,
                     0.0, c.force.x, c.force.y, c.force.z, d.x, d.y, d.z);
    }
  }
  if constexpr (T::has_history) history_->end_pass(nlocal);
  if (rolling_) rolling_fix_->end_pass(nlocal);
}

template <class N>
double PairGranthesis::add_rolling_torque_3d(int i, int j, const PairParameters& p,
                                             const ContactGeometry3& g, double fn, bool advance) {
  if (p.rolling_friction == 0.0) return 0.0;
  double** omega = atom->omega;
  double** torque = atom->torque;
  const int nlocal = atom->nlocal;
  double* kept = rolling_fix_->springs(i, atom->tag[j]);
  double* mirror = j < nlocal ? rolling_fix_->springs(j, atom->tag[i]) : nullptr;
  Vec3 theta = into_tangent_plane(vec(kept), g.normal);
  const Vec3 m =
      RollingLaw::torque<N>(p, g, fn, rolling_spin(vec(omega[i]), vec(omega[j]), g.normal),
                            rolling_inertia(rim_inertia(i), rim_inertia(j)), theta, update->dt);
  if (advance) {
    store(kept, theta);
    if (mirror) store(mirror, -theta);
  }
  add(torque[i], m);
  if (force->newton_pair || j < nlocal) add(torque[j], -m);
  return RollingLaw::elastic_energy<N>(p, g, theta);
}

// single() in 3D: the force on i (x, y, z), the tangential force's size, F_n and the overlap.
double PairGranthesis::single_3d(int i, int j, int itype, int jtype, double rsq, double& fforce) {
  double** x = atom->x;
  double** v = atom->v;
  const Vec3 d{x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
  const double reach = atom->radius[i] + atom->radius[j];
  if (rsq >= reach * reach || rsq == 0.0) return 0.0;
  const ContactGeometry3 g =
      pair_geometry(d, std::sqrt(rsq), atom->radius[i], atom->radius[j], atom->rmass[i],
                    atom->rmass[j], vec(v[i]), vec(v[j]), vec(atom->omega[i]), vec(atom->omega[j]));
  const PairParameters& p = parameters(itype, jtype);
  Vec3 history{}; // the spring as it stands (single changes nothing)
  if (history_)
    if (const double* kept = history_->peek_springs(i, atom->tag[j])) history = vec(kept);
  return with_contact_law(normal_, tangential_, [&]<class N, class T>() {
    const ContactForce3 c = contact_force<N, T>(p, g, history, update->dt);
    fforce = c.normal_force / std::sqrt(rsq);
    svector_storage_[0] = c.force.x;
    svector_storage_[1] = c.force.y;
    svector_storage_[2] = c.force.z;
    svector_storage_[3] = magnitude(c.force - c.normal_force * g.normal);
    svector_storage_[4] = c.normal_force;
    svector_storage_[5] = g.overlap;
    return contact_elastic_energy<N, T>(p, g, history);
  });
}

// compute() instantiates compute_3d through with_contact_law in pair_granthesis.cpp: every law
// pair, here, where the template is defined.
void PairGranthesis::compute_3d_pass(int eflag, int vflag) {
  with_contact_law(normal_, tangential_,
                   [&]<class N, class T>() { compute_3d<N, T>(eflag, vflag); });
}

} // namespace talus::lammps
