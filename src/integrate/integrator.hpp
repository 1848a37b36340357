#pragma once
// Time integration of the free particles. Each scheme is split into the stage before the force
// evaluation (predict) and the stage after it (correct); fixed and moved particles are skipped.
#include <cmath>
#include <string_view>
#include <vector>

#include "state/particles.hpp"

namespace talus {

enum class Integrator { gear, verlet };

std::string_view to_string(Integrator integrator);
/// Parses "gear" / "verlet"; throws InvalidArgument listing the allowed names otherwise.
Integrator parse_integrator(std::string_view name);

/// Corrector weights of the 5-value Gear predictor-corrector for second-order equations with
/// velocity-dependent forces (Poeschel & Schwager 2005, Computational Granular Dynamics; the
/// thesis' eq. 2.4). Position-only forces would use c0 = 19/120.
inline constexpr double gear_c[5] = {19.0 / 90.0, 3.0 / 4.0, 1.0, 1.0 / 2.0, 1.0 / 12.0};

/// Largest timestep at which the integrator keeps an undamped contact oscillation of stiffness k
/// and reduced mass m_eff bounded. Velocity Verlet: omega dt < 2, exactly. Gear (5 values,
/// c0 = 19/90) is weakly unstable on an undamped oscillator: the amplitude grows per step by
/// 1.5e-5 at omega dt = 0.25 and 7.5e-4 at 0.5, roughly as (omega dt)^5.7 (amplification matrix
/// iterated, see docs/model.md); its bound is taken as omega dt = 0.2, where the growth is
/// about 5e-6 per step and far below what contact damping removes.
double max_stable_timestep(Integrator integrator, double stiffness, double m_eff);

/// The Verlet list's drift test, done inside the predictor's loop (one pass less over memory):
/// the predictor reports whether some particle ended farther than sqrt(limit2) from its
/// reference (the list's build position). A reference of another size always reports true.
struct DriftTest {
  const std::vector<Vec2>& reference;
  double limit2;
  /// The build positions, or nullptr when they are not those of these particles (the test then
  /// reports true).
  const Vec2* reference_for(const Particles& p) const {
    return reference.size() == p.size() ? reference.data() : nullptr;
  }
};

/// What a pass that ends one step and begins the next reports.
struct StepSeam {
  bool finite = true; ///< every corrected position and velocity finite
  bool moved = false; ///< the drift test of the prediction: rebuild the list
};

/// Sets the Gear derivatives from the current forces (acceleration = F/m, higher ones 0).
void gear_initialise(Particles& p);
/// Taylor prediction of position, velocity, acceleration and higher derivatives to t + dt.
/// Returns the drift test's answer.
bool gear_predict(Particles& p, double dt, int threads, const DriftTest& drift);
/// Corrects every predicted derivative by the difference of F/m and the predicted acceleration.
/// Returns false if a position or velocity came out non-finite.
bool gear_correct(Particles& p, double dt, int threads);
/// gear_correct, then gear_predict for the next step, particle by particle in one pass over
/// memory (the same arithmetic: the results are bit-identical to the two passes).
StepSeam gear_correct_predict(Particles& p, double dt, int threads, const DriftTest& drift);

/// Velocity Verlet's first half kick and drift for particle i (half = dt / 2), with the forces
/// in `force` and no branch on the kind: fixed and moved particles have inv_mass = 0 (no kick),
/// fixed ones are at rest and drivers overwrite moved ones. The velocity it leaves is the
/// prediction v(t) + dt a(t) the contact laws see. Returns whether the particle ended farther
/// than sqrt(limit2) from its reference (none given: false).
inline bool verlet_predict_one(Particles& p, std::size_t i, double dt, double half,
                               const Vec2* reference, double limit2) {
  const Vec2 kick = half * p.inv_mass[i] * p.force[i];
  p.position[i] += dt * (p.velocity[i] + kick);
  const bool far = reference != nullptr && norm2(p.position[i] - reference[i]) > limit2;
  p.velocity[i] += 2.0 * kick; // predicted v(t + dt)
  const double spin_kick = half * p.inv_inertia[i] * p.torque[i];
  p.angle[i] += dt * (p.angular_velocity[i] + spin_kick);
  p.angular_velocity[i] += 2.0 * spin_kick;
  return far;
}

/// Velocity Verlet: half kick with the old forces, then drift; F(t) moves to force_previous (the
/// force stage must then set every force). Returns the drift test's answer.
bool verlet_predict(Particles& p, double dt, int threads, const DriftTest& drift);
/// Velocity Verlet's second half kick for particle i, with the new forces (half = dt / 2): it
/// replaces the predicted one. The force stage calls it for each particle as soon as that
/// particle's force is complete (one pass less over memory), and inside Simulation::run
/// verlet_predict_one for the next step right after it. Returns false if the particle's
/// velocity came out non-finite (a non-finite position or force makes it so).
inline bool verlet_correct_one(Particles& p, std::size_t i, double half) {
  p.velocity[i] += half * p.inv_mass[i] * (p.force[i] - p.force_previous[i]);
  p.angular_velocity[i] += half * p.inv_inertia[i] * (p.torque[i] - p.torque_previous[i]);
  return std::isfinite(p.velocity[i].x + p.velocity[i].y + p.angular_velocity[i]);
}

} // namespace talus
