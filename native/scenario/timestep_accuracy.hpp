#pragma once
// What the run's timestep costs in restitution, from validation/work_precision.py's findings
// (docs/accuracy.md): the linear dashpot's force jumps at the touch, an error of first order
// in dt for any integrator; the Hertz law's starts from zero, an error of second order.
#include <string>

#include "scenario/build.hpp"

namespace talus {

/// The largest relative restitution error the timestep makes on the pairs that can meet, about,
/// and what it rests on ("": no estimate for this law or scene).
struct RestitutionError {
  double error = 0.0;
  std::string basis;
};

/// The estimate for a built scenario: the linear law's pi zeta dt / t_c with the largest
/// damping ratio zeta of the pairs that can meet and the shortest collision time; the Hertz
/// law's from the measured errors of docs/accuracy.md at dt / t_c and the lowest restitution of
/// the pairs that can meet.
RestitutionError expected_restitution_error(const BuiltScenario& b);

/// Hertz: the largest measured relative restitution error at t_c / dt = factor and restitution
/// e (docs/accuracy.md's table, the worse of Gear and Verlet: log-log in the factor, beyond its
/// ends the second-order trend; the log of the error linear in e between the measured e, and
/// the nearest measured e outside 0.1 to 0.99).
double hertz_restitution_error(double factor, double restitution);

} // namespace talus
