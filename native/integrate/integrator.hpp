#pragma once
// Time integration of the free particles. Each scheme is split into the stage before the force
// evaluation (predict) and the stage after it (correct); fixed and moved particles are skipped.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

#include "core/lanes.hpp"
#include "state/particles.hpp"

namespace talus {

enum class Integrator { gear, verlet };

/// The velocity velocity Verlet gives the contact laws while F(t + dt) is computed: the
/// prediction v(t) + dt a(t) (Groot & Warren 1997, lambda = 1: damping lags by O(dt^2)), or the
/// half-step v(t) + dt/2 a(t) of LAMMPS' fix nve/sphere (lambda = 1/2: it lags by O(dt)), with
/// which the native engine reproduces LAMMPS to rounding. Positions and the velocities after a
/// step are velocity Verlet's either way.
enum class VerletVelocity : std::uint8_t { predicted, half_step };

std::string_view to_string(VerletVelocity v);
/// Parses "predicted" / "half_step"; throws InvalidArgument listing the allowed names otherwise.
VerletVelocity parse_verlet_velocity(std::string_view name);
/// The share of dt/2 a(t) the force-time velocity carries beyond the half kick: 1 (predicted) or
/// 0 (half_step). Multiplying by 1 and adding 1 are exact, so the default's bits are unchanged.
inline double verlet_lag(VerletVelocity v) {
  return v == VerletVelocity::predicted ? 1.0 : 0.0;
}

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

/// What a pass over the particles reports: whether it kept them finite, and how far it moved the
/// farthest one, for the neighbour list's drift bound (Simulation: the list is tested against its
/// build positions only when the sum of these over the passes since the build could have reached
/// half the skin).
struct PassReport {
  bool finite = true;       ///< every corrected position and velocity finite
  double displacement2 = 0; ///< the largest squared displacement of a free particle (m^2)
};

/// The force and torque every force stage starts particle k from, before the contacts add to
/// them: its weight if it is free, else none. The fused passes (velocity Verlet's in the force
/// stage, gear_correct_predict) write them for the next step while the lines are in cache, so
/// that the next force stage needs no pass of its own over memory to set them. A step without
/// gravity (Gravity false) starts every force from 0, and one without rotation leaves the torques
/// at the 0 they keep (step_features.hpp).
template <bool Gravity = true, bool Rotation = true>
inline void start_forces(const Particles& p, std::size_t k, Vec2 gravity, Vec2* force,
                         double* torque) {
  if constexpr (Gravity)
    force[k] = p.kind[k] == Kind::free ? p.mass[k] * gravity : Vec2{};
  else
    force[k] = Vec2{};
  if constexpr (Rotation) torque[k] = 0.0;
}

/// Sets the Gear derivatives from the current forces (acceleration = F/m, higher ones 0).
void gear_initialise(Particles& p);
/// Taylor prediction of position, velocity, acceleration and higher derivatives to t + dt.
/// Returns the largest squared displacement. Without `rotation` (no grain turns, and none can:
/// step_features.hpp) the angles and their derivatives are left as they are: the same bits as
/// integrating their zeros.
double gear_predict(Particles& p, double dt, int threads, bool rotation = true);
/// Corrects every predicted derivative by the difference of F/m and the predicted acceleration.
/// `finite` is false if a position or velocity came out non-finite.
PassReport gear_correct(Particles& p, double dt, int threads, bool rotation = true);
/// gear_correct, then gear_predict for the next step, particle by particle in one pass over
/// memory (the same arithmetic: the results are bit-identical to the two passes). The
/// displacement is that of both together. It leaves every force and torque as the next force
/// stage starts them (start_forces, with `gravity`). Without `weight` (gravity is (0, 0)) the
/// forces start from 0 with no look at the particles' kind and mass.
PassReport gear_correct_predict(Particles& p, double dt, Vec2 gravity, int threads,
                                bool rotation = true, bool weight = true);

/// Velocity Verlet's first half kick and drift for particle i (half = dt / 2), with the forces
/// in `force` and no branch on the kind: fixed and moved particles have inv_mass = 0 (no kick),
/// fixed ones are at rest and drivers overwrite moved ones. The velocity it leaves is the one the
/// contact laws see: v(t) + (1 + lag) dt/2 a(t) (lag: verlet_lag). Returns the squared
/// displacement. Without Rotation the angle and its velocity are left as they are.
template <bool Rotation = true>
inline double verlet_predict_one(Particles& p, std::size_t i, double dt, double half, double lag) {
  const Vec2 kick = half * p.inv_mass[i] * p.force[i];
  const Vec2 displacement = dt * (p.velocity[i] + kick);
  p.position[i] += displacement;
  p.velocity[i] += (1.0 + lag) * kick; // predicted v(t + dt), or the half step's
  if constexpr (Rotation) {
    const double spin_kick = half * p.inv_inertia[i] * p.torque[i];
    p.angle[i] += dt * (p.angular_velocity[i] + spin_kick);
    p.angular_velocity[i] += (1.0 + lag) * spin_kick;
  }
  return norm2(displacement);
}

/// Velocity Verlet: half kick with the old forces, then drift; F(t) moves to force_previous (the
/// force stage must then set every force). Returns the largest squared displacement.
double verlet_predict(Particles& p, double dt, int threads, double lag, bool rotation = true);
/// Velocity Verlet's second half kick for particle i, with the new forces (half = dt / 2): it
/// replaces the predicted one. The force stage calls it for each particle as soon as that
/// particle's force is complete (one pass less over memory), and inside Simulation::run
/// verlet_predict_one for the next step right after it. Returns false if the particle's
/// velocity came out non-finite (a non-finite position or force makes it so).
template <bool Rotation = true>
inline bool verlet_correct_one(Particles& p, std::size_t i, double half, double lag) {
  p.velocity[i] += half * p.inv_mass[i] * (p.force[i] - lag * p.force_previous[i]);
  if constexpr (!Rotation) return std::isfinite(p.velocity[i].x + p.velocity[i].y);
  p.angular_velocity[i] += half * p.inv_inertia[i] * (p.torque[i] - lag * p.torque_previous[i]);
  return std::isfinite(p.velocity[i].x + p.velocity[i].y + p.angular_velocity[i]);
}

/// verlet_correct_one for every particle, as a pass of its own: for a step whose forces are
/// completed after the force stage (rolling resistance). Returns whether every velocity is
/// finite.
bool verlet_correct(Particles& p, double dt, int threads, double lag);

/// verlet_correct_one, then verlet_predict_one, for particles k and k + 1 side by side, one per
/// lane of an SSE2 register (core/lanes.hpp): operation for operation the same arithmetic, so
/// the same bits (tests FusedSteps.*), with the two particles' values loaded and stored together.
/// Clears a lane of `finite` for a non-finite corrected velocity; returns
/// the squared displacements.
template <bool Rotation = true>
inline Lanes verlet_correct_predict_two(Particles& p, std::size_t k, double dt, double half,
                                        double lag, LaneMask& finite) {
  // every load before the first store: the stores cannot change what is still to be read
  const Lanes hm = half * lanes_at(p.inv_mass.data() + k);
  const auto [fx, fy] = components_at(p.force.data() + k);
  const auto [gx, gy] = components_at(p.force_previous.data() + k);
  const auto [vx0, vy0] = components_at(p.velocity.data() + k);
  const auto [x0, y0] = components_at(p.position.data() + k);
  // the correction
  const Lanes vx = vx0 + hm * (fx - lag * gx), vy = vy0 + hm * (fy - lag * gy);
  const double ahead = 1.0 + lag;
  const Lanes kick_x = hm * fx, kick_y = hm * fy;
  const Lanes dx = dt * (vx + kick_x), dy = dt * (vy + kick_y);
  if constexpr (Rotation) {
    const Lanes hi = half * lanes_at(p.inv_inertia.data() + k);
    const Lanes torque = lanes_at(p.torque.data() + k);
    const Lanes torque_previous = lanes_at(p.torque_previous.data() + k);
    const Lanes w0 = lanes_at(p.angular_velocity.data() + k);
    const Lanes angle0 = lanes_at(p.angle.data() + k);
    const Lanes w = w0 + hi * (torque - lag * torque_previous);
    finite &= magnitude(vx + vy + w) <= std::numeric_limits<double>::max();
    const Lanes spin_kick = hi * torque;
    store_lanes(p.angle.data() + k, angle0 + dt * (w + spin_kick));
    store_lanes(p.angular_velocity.data() + k, w + ahead * spin_kick);
  } else {
    finite &= magnitude(vx + vy) <= std::numeric_limits<double>::max();
  }
  // the prediction
  store_components(p.position.data() + k, x0 + dx, y0 + dy);
  store_components(p.velocity.data() + k, vx + ahead * kick_x, vy + ahead * kick_y);
  return dx * dx + dy * dy;
}

} // namespace talus
