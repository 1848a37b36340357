#include "analysis/energy_ledger.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "core/contact_vectors.hpp"
#include "simulation/rolling_pass.hpp"
#include "talus/error.hpp"
#include "talus/law_table.hpp"
#include "talus/rolling_resistance.hpp"

namespace talus {

namespace {

// A contact's share of the powers. The relative motion's power F_n v_n + F_t v_t is what the
// contact force does on both members together (the lever arms make the torques' part exact);
// the free members' power beyond it comes from a wall's motion.
// The rolling torque's share (rolling_resistance.hpp): its power on the relative spin is
// friction's, on a wall's rotation the wall's work; its spring's energy is stored like the
// tangential spring's. Adds the torque's power on the free members to `into_free`.
template <class N>
void add_rolling(const World& w, const ContactView& v, double normal_force, bool free_i,
                 bool free_j, ContactPowers& out, double& relative, double& into_free) {
  const Particles& p = w.particles;
  const RollingKinematics k = rolling_kinematics(w, v.i, v.j, v.wall);
  double theta = v.rolling; // a copy: looking must not advance the spring
  const double m =
      RollingLaw::torque<N>(*v.parameters, v.geometry, normal_force, k.spin, k.inertia, theta, 0.0);
  out.tangential -= m * k.spin;
  relative += m * k.spin;
  if (free_i) into_free += m * p.angular_velocity[v.i];
  if (free_j) into_free -= m * p.angular_velocity[v.j];
  out.tangential_elastic += RollingLaw::elastic_energy<N>(*v.parameters, v.geometry, v.rolling);
}

template <class N, class T>
void add_contact(const World& w, const ContactView& v, ContactPowers& out) {
  const Particles& p = w.particles;
  const bool free_i = p.is_free(v.i), free_j = v.wall < 0 && p.is_free(v.j);
  if (!free_i && !free_j) return;
  const ContactGeometry& g = v.geometry;
  double history = v.history; // a copy: looking must not advance the spring
  const ContactForce f = contact_force<N, T>(*v.parameters, g, history, 0.0);
  ContactGeometry at_rest = g; // the elastic part of the normal force: the force without motion
  at_rest.v_normal = 0.0;
  const double elastic = N::force(*v.parameters, at_rest);
  const Vec2 force = force_of(f);
  const double tangential = dot(force, tangent_of(g));
  double relative = f.normal_force * g.v_normal + tangential * g.v_tangent;
  out.damper -= (f.normal_force - elastic) * g.v_normal;
  out.tangential -= tangential * g.v_tangent;
  double into_free = 0.0;
  if (v.parameters->rolling_friction > 0.0)
    add_rolling<N>(w, v, not_below_zero(f.normal_force), free_i, free_j, out, relative, into_free);
  if (!free_i || !free_j) {
    if (free_i) into_free += dot(force, p.velocity[v.i]) + f.torque_i * p.angular_velocity[v.i];
    if (free_j) into_free += -dot(force, p.velocity[v.j]) + f.torque_j * p.angular_velocity[v.j];
    out.walls += into_free - relative;
  }
  if constexpr (T::has_history) {
    const double kt = T::stiffness(*v.parameters, g, N::stiffness(*v.parameters, g));
    out.tangential_elastic += 0.5 * kt * v.history * v.history;
  }
}

} // namespace

ContactPowers contact_powers(const Simulation& sim) {
  ContactPowers out;
  const SimulationConfig& c = sim.config();
  with_contact_law(c.normal_law, c.tangential_law, [&]<class N, class T>() {
    sim.for_each_contact([&](const ContactView& v) { add_contact<N, T>(sim.world(), v, out); });
  });
  return out;
}

void EnergyLedger::start(const ContactPowers& now, double time, double total) {
  last_ = now;
  last_time_ = time;
  damper_ = tangential_ = walls_ = 0.0;
  start_total_ = total;
  start_tangential_elastic_ = now.tangential_elastic;
}

void EnergyLedger::observe(const ContactPowers& now, double time) {
  const double h = time - last_time_;
  damper_ += 0.5 * h * (last_.damper + now.damper);
  tangential_ += 0.5 * h * (last_.tangential + now.tangential);
  walls_ += 0.5 * h * (last_.walls + now.walls);
  last_ = now;
  last_time_ = time;
}

void EnergyLedger::changed(const ContactPowers& now, double total_before, double total_now) {
  start_total_ += total_now - total_before;
  // friction's dissipation is its work less the springs' energy gained: a spring the change
  // took away was not dissipated
  start_tangential_elastic_ += now.tangential_elastic - last_.tangential_elastic;
  last_ = now;
}

LedgerRow EnergyLedger::row(double total, double mechanical) {
  LedgerRow r;
  r.dissipated_damper = damper_;
  r.dissipated_friction = tangential_ - (last_.tangential_elastic - start_tangential_elastic_);
  r.wall_work = walls_;
  r.imbalance = total + r.dissipated_damper + r.dissipated_friction - r.wall_work - start_total_;
  largest_mechanical_ = std::max(largest_mechanical_, mechanical);
  const double in_play = largest_mechanical_ + std::abs(r.dissipated_damper) +
                         std::abs(r.dissipated_friction) + std::abs(r.wall_work);
  r.rise = r.imbalance - lowest_imbalance_;
  r.growth = in_play > 0.0 ? r.rise / in_play : 0.0;
  lowest_imbalance_ = std::min(lowest_imbalance_, r.imbalance);
  return r;
}

void start_ledger(EnergyLedger& ledger, const Simulation& sim) {
  ledger.start(contact_powers(sim), sim.time(), energies(sim).total());
}

void observe_ledger(EnergyLedger& ledger, const Simulation& sim) {
  ledger.observe(contact_powers(sim), sim.time());
}

LedgerRow ledger_row(EnergyLedger& ledger, const Energies& e) {
  return ledger.row(e.total(), e.kinetic() + e.elastic);
}

std::vector<double> EnergyLedger::save() const {
  return {last_.damper,      last_.tangential,
          last_.walls,       last_.tangential_elastic,
          last_time_,        damper_,
          tangential_,       walls_,
          start_total_,      start_tangential_elastic_,
          lowest_imbalance_, largest_mechanical_};
}

void EnergyLedger::load(const std::vector<double>& s) {
  if (s.size() != 12)
    throw InvalidArgument("checkpoint: the energy ledger holds " + std::to_string(s.size()) +
                          " numbers, expected 12");
  last_ = {s[0], s[1], s[2], s[3]};
  last_time_ = s[4];
  damper_ = s[5];
  tangential_ = s[6];
  walls_ = s[7];
  start_total_ = s[8];
  start_tangential_elastic_ = s[9];
  lowest_imbalance_ = s[10];
  largest_mechanical_ = s[11];
}

std::string ledger_thermo_columns(const LedgerRow& row) {
  return fmt::format(",{:.9e},{:.9e},{:.9e},{:.9e}", row.dissipated_damper, row.dissipated_friction,
                     row.wall_work, row.imbalance);
}

std::string energy_growth_words(std::uint64_t step, double time, double timestep,
                                const LedgerRow& row) {
  return fmt::format(
      "unstable at step {} (t = {:.6g} s, dt = {:.4g} s): the energy grew by {:.3g} J, {:.2g} "
      "of the energy in play, that no damper, friction or driven wall accounts for (the energy "
      "ledger; limit {:g})",
      step, time, timestep, row.rise, row.growth, ledger_growth_limit);
}

std::string energy_growth_diagnosis(const Simulation& sim, const LedgerRow& row,
                                    double collision_time) {
  const Particles& p = sim.world().particles;
  const SimulationConfig& c = sim.config();
  double shortest = std::numeric_limits<double>::infinity(), ratio = 0.0;
  std::string pair;
  with_normal_law(c.normal_law, [&]<class N>() {
    sim.for_each_contact([&](const ContactView& v) {
      const double k = N::stiffness(*v.parameters, v.geometry);
      if (!(k > 0.0)) return;
      const double tc = std::numbers::pi * std::sqrt(v.geometry.m_eff / k);
      if (tc >= shortest) return;
      shortest = tc;
      const double smaller = v.wall < 0 ? std::min(p.radius[v.i], p.radius[v.j]) : p.radius[v.i];
      ratio = v.geometry.overlap / smaller;
      pair = fmt::format("particle id {} and {}", p.id[v.i],
                         v.wall < 0 ? fmt::format("particle id {}", p.id[v.j])
                                    : fmt::format("wall segment {}", v.wall));
    });
  });
  std::string msg = energy_growth_words(sim.step_count(), sim.time(), c.timestep, row);
  if (std::isfinite(shortest)) {
    msg += fmt::format(". The stiffest contact now, between {} at an overlap of {:.2g} of the "
                       "smaller radius, lasts about {:.3g} s: {:.3g} steps",
                       pair, ratio, shortest, shortest / c.timestep);
    if (collision_time > 0.0 && shortest < 0.8 * collision_time)
      return msg + fmt::format(", where the timestep was chosen for contacts of {:.3g} s. The "
                               "contacts have stiffened (a Hertz contact does as its overlap "
                               "grows) past what the timestep integrates: a timestep of about "
                               "{:.3g} s (that contact's time / 50), or velocity Verlet, which "
                               "is stable to larger ones (docs/accuracy.md).",
                               collision_time, shortest / 50.0);
  } else {
    msg += ". No contact touches now (those that grew it have ended)";
  }
  const double steps = collision_time / c.timestep;
  if (collision_time > 0.0 && steps < Simulation::min_steps_per_contact)
    return msg + fmt::format(". The timestep resolves the run's collision time ({:.3g} s) in "
                             "{:.3g} steps: it is too large; a timestep of about {:.3g} s "
                             "(collision time / 50) would resolve it.",
                             collision_time, steps, collision_time / 50.0);
  return msg + fmt::format(". The contacts are as stiff as the timestep was chosen for ({:.3g} "
                           "steps per collision time); a smaller timestep (about the collision "
                           "time / 50), or the other integrator, may be stable (the limits of "
                           "both: docs/accuracy.md).",
                           steps);
}

} // namespace talus
