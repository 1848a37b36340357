#pragma once
// The servo controller of a wall held at a target load (docs/model.md, "Servo walls"). It is
// the servo of Itasca's PFC, v = alpha (F_target - F) / (K dt), with the wall's contact
// dashpots taken into account: with dashpots, the load answers a change of the wall's speed at
// once, and the plain rule, which ignores that, makes the speed flip sign from step to step
// once alpha C / (K dt) > 1 (C the dashpots' sum), which a few steps per contact damping time
// reach.
#include "drivers/drivers.hpp"

namespace talus {

/// What the wall's contacts say after a step: the load along -direction (the grains' push on
/// the wall), the sum of the contacts' tangent normal stiffnesses dF/dxi and of their normal
/// damping coefficients dF/d(dxi/dt).
struct ServoReading {
  double load = 0.0;      ///< N
  double stiffness = 0.0; ///< N/m
  double damping = 0.0;   ///< N s/m
};

/// The wall's speed for the next step. The grains held still, moving at v for a step of dt
/// changes the load by K v dt + C (v - v_last); setting that to alpha times the error gives
///   v = (alpha (F_target - F) + C v_last) / (K dt + C),
/// whose dependence on v_last, C / (K dt + C), is below 1: stable, whatever the dashpots. With no
/// contact the wall moves at max_speed towards the grains (or away, for a negative target).
/// Never faster than max_speed either way.
double servo_speed(const Servo& s, const ServoReading& r, double dt);
/// The same rule for any wall (a 3D plate's servo too): `target` the load wanted (N),
/// `last_speed` the speed chosen after the step before.
double servo_speed(double target, double relaxation, double max_speed, double last_speed,
                   const ServoReading& r, double dt);

/// Takes the speed for the next step and moves the controller's displacement by it.
void servo_advance(Servo& s, const ServoReading& r, double dt);

} // namespace talus
