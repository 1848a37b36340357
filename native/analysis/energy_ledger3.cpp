#include "analysis/energy_ledger3.hpp"

#include <fmt/format.h>

#include "engine3d/contact_visit3.hpp"
#include "engine3d/rolling3.hpp"
#include "talus/law_table.hpp"

namespace talus {

namespace {

// The two members of a contact: a sphere j, or a plate (j = none) moving with velocity and spin
// at the contact point.
struct Member {
  bool free = false;
  Vec3 velocity, spin;
  double rim = 0.0; // inertia about the rim, for rolling resistance's dashpot; 0: a plate
};

// As the 2D ledger's add_contact: the relative motion's power F_n v_n + F_t.v_t (and the rolling
// torque's on the relative spin) is what the contact does on both members together; the free
// members' power beyond it comes from a plate's motion.
template <class N, class T>
void add_contact(const ContactGeometry3& g, const PairParameters& p, const Vec3& spring,
                 const Vec3* rolling, const Member& i, const Member& j, ContactPowers& out) {
  if (!i.free && !j.free) return;
  Vec3 history = spring; // a copy: looking must not advance the spring
  const ContactForce3 f = contact_force<N, T>(p, g, history, 0.0);
  ContactGeometry3 at_rest = g; // the elastic part of the normal force: the force without motion
  at_rest.v_normal = 0.0;
  const double elastic = N::force(p, at_rest);
  const Vec3 tangential = f.force - f.normal_force * g.normal;
  double relative = f.normal_force * g.v_normal + dot(tangential, g.v_tangent);
  out.damper -= (f.normal_force - elastic) * g.v_normal;
  out.tangential -= dot(tangential, g.v_tangent);
  Vec3 torque_i = f.torque_i, torque_j = f.torque_j;
  if (rolling != nullptr && p.rolling_friction > 0.0) {
    Vec3 theta = *rolling;
    const Vec3 m =
        rolling_torque<N>(p, g, f.normal_force, i.spin, j.spin, i.rim, j.rim, theta, 0.0);
    const double on_relative = dot(m, rolling_spin(i.spin, j.spin, g.normal));
    out.tangential -= on_relative;
    relative += on_relative;
    torque_i += m, torque_j -= m;
    out.tangential_elastic += rolling_energy<N>(p, g, *rolling);
  }
  if (!i.free || !j.free) {
    double into_free = 0.0;
    if (i.free) into_free += dot(f.force, i.velocity) + dot(torque_i, i.spin);
    if (j.free) into_free += -dot(f.force, j.velocity) + dot(torque_j, j.spin);
    out.walls += into_free - relative;
  }
  if constexpr (T::has_history) {
    const double kt = T::stiffness(p, g, N::stiffness(p, g));
    out.tangential_elastic += 0.5 * kt * norm2(into_tangent_plane(spring, g.normal));
  }
}

} // namespace

ContactPowers contact_powers(const Simulation3& sim) {
  ContactPowers out;
  const Scene3& scene = sim.scene();
  const Spheres& s = scene.spheres;
  const SphereList& list = sim.list();
  const Settings3& c = sim.settings();
  const auto sphere = [&](std::uint32_t k) {
    return Member{s.is_free(k), s.velocity[k], s.angular_velocity[k], rim_of(s, k)};
  };
  with_contact_law(c.normal_law, c.tangential_law, [&]<class N, class T>() {
    for_each_contact3(
        scene, list, sim.table(), lever_shares(c.lever_arm),
        [&](std::uint32_t i, std::uint32_t e, std::uint32_t j, const ContactGeometry3& g,
            const PairParameters& p) {
          add_contact<N, T>(g, p, list.spring_at(e), list.with_rolling ? &list.rolling[e] : nullptr,
                            sphere(i), sphere(j), out);
        },
        [&](std::uint32_t i, std::uint32_t e, std::uint32_t w, const ContactGeometry3& g,
            const PairParameters& p) {
          const Plane& plate = scene.plates[w];
          const Member at_plate{false, plate.velocity_at(closest_point(plate, s.position[i])),
                                plate.angular_velocity, 0.0};
          add_contact<N, T>(g, p, list.plate_spring_at(e),
                            list.with_rolling ? &list.plate_rolling[e] : nullptr, sphere(i),
                            at_plate, out);
        });
  });
  return out;
}

void start_ledger(EnergyLedger& ledger, const Simulation3& sim) {
  ledger.start(contact_powers(sim), sim.time(), sim.energies().total());
}

void observe_ledger(EnergyLedger& ledger, const Simulation3& sim) {
  ledger.observe(contact_powers(sim), sim.time());
}

LedgerRow ledger_row(EnergyLedger& ledger, const Energies3& e) {
  return ledger.row(e.total(), e.kinetic + e.rotational + e.elastic);
}

std::string energy_growth_diagnosis(const Simulation3& sim, const LedgerRow& row,
                                    double collision_time) {
  const double dt = sim.settings().timestep;
  std::string msg = energy_growth_words(sim.step_count(), sim.time(), dt, row);
  if (sim.contact_count() > 0)
    msg += ". The deepest contact now: " + deepest_contact(sim.scene(), sim.list(), sim.settings());
  return msg + fmt::format(". The timestep resolves the collision time it was chosen for "
                           "({:.3g} s) in {:.3g} steps; a smaller timestep (about the collision "
                           "time / 50), or the other integrator, may be stable (docs/accuracy.md)",
                           collision_time, collision_time / dt);
}

} // namespace talus
