#pragma once
// Single-contact closed forms: collision time, restitution <-> damping, stable timestep.
// m_eff = m_i m_j / (m_i + m_j), r_eff = R_i R_j / (R_i + R_j); for a wall, m_eff = m, r_eff = R.

namespace talus {

// ---- linear spring-dashpot: m xi'' = -max(0, k xi + eta xi') ----------------------------------
// With beta = eta / (2 m), omega = sqrt(k/m - beta^2) and x = beta / omega. Because the force is
// never attractive, the grains part when it vanishes, before the overlap does (Schwager &
// Poeschel 2007, Granular Matter 9, 465): e = exp(-x (pi - 2 atan x)), and the overlap returns to
// zero after t_c = (pi - 2 atan x + sin(2 atan x)) / omega. For weak damping these tend to the
// textbook e = exp(-pi x) and t_c = pi / omega. The lowest reachable restitution is e^-2.

/// The damping ratio zeta = eta / (2 sqrt(k m)) that gives restitution e (exact, by bisection).
double linear_damping_ratio(double restitution);
/// Restitution of the (never attractive) linear spring-dashpot contact.
double linear_restitution(double stiffness, double dashpot, double m_eff);
/// Duration of the overlap of the (never attractive) linear spring-dashpot contact.
double linear_collision_time(double stiffness, double dashpot, double m_eff);
/// The textbook values for a dashpot allowed to pull: e = exp(-pi beta/omega), t_c = pi/omega.
double linear_restitution_textbook(double stiffness, double dashpot, double m_eff);
double linear_collision_time_textbook(double stiffness, double dashpot, double m_eff);

// ---- Hertzian viscoelastic: m xi'' = -rho (xi^3/2 + 3/2 A sqrt(xi) xi'), rho = 4/3 E* sqrt(R*) -

double hertz_rho(double effective_young, double r_eff);
/// Elastic collision duration at impact speed v: t_c = c (m_eff / rho)^(2/5) v^(-1/5), with the
/// exact c = 2 (5/4)^(2/5) sqrt(pi) Gamma(7/5) / Gamma(9/10) = 3.2181 (2.868 in terms of E*, R*).
double hertz_collision_time(double m_eff, double rho, double impact_speed);
/// Elastic maximum overlap: (5 m_eff v^2 / (4 rho))^(2/5).
double hertz_max_overlap(double m_eff, double rho, double impact_speed);
/// Restitution of the viscoelastic law at impact speed v, by accurate integration of the
/// single-contact equation (relative error below 1e-8).
double hertz_restitution(double damping_A, double m_eff, double rho, double impact_speed);
/// The A that gives restitution e at impact speed v (inverse of hertz_restitution, by bisection).
double hertz_damping_for_restitution(double restitution, double m_eff, double rho,
                                     double impact_speed);

// ---- stability ------------------------------------------------------------------------------

/// Largest stable step of velocity Verlet for an undamped oscillator of stiffness k: 2/omega.
/// (For the Gear predictor-corrector see max_stable_timestep in integrate/integrator.hpp.)
double verlet_stable_timestep(double stiffness, double m_eff);

} // namespace talus
