#pragma once
// Reference numbers for the physics validation tests, with their sources. Every tolerance used
// by a test is here too, with the reason it is what it is.

namespace talus::reference {

// ---- thesis chapter 3: the two-disk validation collisions ----------------------------------
/// Impact speed of each disk in the thesis' head-on and oblique tests, m/s (sec. 3.2.1).
inline constexpr double thesis_disk_speed = 0.01;
/// Elastic collisions conserve total energy; the issue asks for 1e-6 relative. What limits any
/// integrator here is the kink of the force at first touch (F = 0 for xi < 0, k xi after): the
/// error depends on where the touch falls between steps and is the same for Gear and Verlet
/// (measured: 2e-4 for an oblique collision at dt = t_c/50, 1e-6 at t_c/400, 1e-8 at t_c/1600).
/// The conservation tests therefore resolve the contact with t_c/1600 steps.
inline constexpr double elastic_energy_tolerance = 1.0e-6;
inline constexpr double conservation_steps_per_collision = 1600.0;
/// Gear's predictor does not conserve r x v exactly: 1.8e-6 relative at t_c/50, 4e-7 at t_c/100
/// (second order), so at t_c/1600 the bound is 1.8e-6 / 32^2 x safety 2.
inline constexpr double gear_angular_momentum_tolerance = 4.0e-9;
/// Round-off: momenta are sums of ~1e4 steps of pairwise-opposite increments of size ~1e-16
/// relative; 1e-12 relative leaves room for that accumulation and nothing else.
inline constexpr double roundoff_tolerance = 1.0e-12;

// ---- linear spring-dashpot -----------------------------------------------------------------
/// Issue 2: e = exp(-pi b / omega), t_c = pi / omega within 0.5% at dt = t_c / 50. Schwager &
/// Poeschel (Granular Matter 9, 465, 2007) give the exact values for the never-attractive force:
/// e = exp(-x (pi - 2 atan x)), x = b / omega; the textbook form is met within 0.5% for x small.
inline constexpr double linear_tolerance = 0.005;
inline constexpr double linear_steps_per_collision = 50.0;

// ---- tangential springs ----------------------------------------------------------------------
/// A disk that hits a flat wall obliquely and sticks (mu large) on undamped linear normal and
/// tangential springs: the contact point's tangential velocity turns as cos(omega_t t), with
/// omega_t^2 = k_t (1 + m R^2 / I) / m = 3 kappa omega_n^2 for a disk, for the contact time
/// pi / omega_n, so it leaves with u' / u = cos(pi sqrt(3 kappa)) (Cundall & Strack 1979's spring;
/// the effective tangential mass m / (1 + m R^2 / I) is Maw, Barber & Fawcett 1976's). The
/// tolerance is the sum of two bounds on the phase (up to 5 rad): the lever arm R - xi/2 the
/// engine uses shortens the arm by up to xi_max / (2 R) = 0.04% at 0.0025 m/s, which speeds
/// omega_t by up to 0.03% (0.0012 rad), and the touch falls between steps, which shifts the
/// spring by up to one step's turn, omega_t dt <= 0.0031 rad at t_c / 1600.
inline constexpr double sticking_tangential_tolerance = 0.005;

// ---- friction's energy (test_friction_energy.cpp) --------------------------------------------
/// The ledger integrates friction's power by trapezoids between looks after each step. At a
/// touch, at a slip-stick transition and at a reversal the force turns within a step, so one
/// step's figure can be off by part of that step's work: at t_c / 50 up to 2.8e-5 of the impact's
/// energy (measured over 48 random impacts). The old spring reset, which let friction push along
/// the slip, gave steps of -1.6 times the grain's energy on the same cases.
inline constexpr double friction_step_tolerance = 1.0e-4;
/// The ledger's balance after an oblique impact at t_c / 50: up to 6.4e-4 of the impact's energy
/// measured (the same trapezoids, at the touch and the parting, where the power jumps).
inline constexpr double impact_balance_tolerance = 2.0e-3;
/// A grain on a floor shaken sideways, dt = 2e-5 s (some 1500 steps a cycle): the balance's error
/// is 1.5e-7 of the floor's work and the worst step 1.8e-7 of the dissipation (measured); the
/// old reset gave steps of -0.55 to -0.66 of the whole dissipation.
inline constexpr double shear_balance_tolerance = 1.0e-5;
inline constexpr double shear_step_tolerance = 1.0e-5;
/// An elastic sticking impact resolved in 800 steps: the spring sums the slip at each step's
/// end, first order in the step: 3.1e-3 off the closed form at t_c / 800 and 6.2e-3 at t_c / 400
/// (measured, linear law; 2.7e-3 against the Hertz reference).
inline constexpr double sticking_steps_per_collision = 800.0;
inline constexpr double sticking_reversal_tolerance = 5.0e-3;
/// An impact that slides throughout: the tangential impulse is mu times the normal one to
/// round-off (3.6e-14 measured: sums over some 50 steps).
inline constexpr double sliding_impulse_tolerance = 1.0e-12;

// ---- oblique elastic impacts (test_oblique_impact_theory.cpp) --------------------------------
/// Maw, Barber & Fawcett's theory by the method of dimensionality reduction: springs along the
/// contact's diameter and leapfrog steps over t_c. At half these (800 springs, 2000 steps) psi2
/// moves by 2e-4 at most, so the reference is good to 1e-3 of the psi scale (the order of 1).
inline constexpr int mbf_reference_springs = 1600;
inline constexpr int mbf_reference_steps = 4000;
inline constexpr double mbf_reference_tolerance = 2.0e-3;
/// talus' impacts at t_c / 200. Sliding throughout, psi2 = psi1 - 4 chi holds but for the touch
/// and the parting, which fall within a step: 6.2e-6 off at most (measured).
inline constexpr double mbf_steps_per_collision = 200.0;
inline constexpr double mbf_sliding_tolerance = 1.0e-4;
/// Where the contact sticks for a while (0 < psi1 < 4 chi - 1), the one spring's rebound lies
/// above the theory's: measured at nu = 0.3 over psi1 = 0.25 to 4 chi - 1.25 in steps of 0.25,
/// at most 0.436 for a sphere (chi = 1.441) and 0.363 for a disk (chi = 1.235), largest near
/// psi1 = 1 to 1.25, where the theory's contact slips at its edge while talus' spring sticks. The
/// bounds hold that miss with a margin of about 0.02; the total-displacement spring (F_t = -k_t s
/// at the current k_t) misses by 0.565 and 0.414 and fails them.
inline constexpr double mbf_intermediate_bound_sphere = 0.46;
inline constexpr double mbf_intermediate_bound_disk = 0.39;

// ---- Hertz -----------------------------------------------------------------------------------
/// t_c = 2.868 (m*^2 / (R* E*^2 v))^(1/5) (Landau & Lifshitz, Theory of Elasticity, sec. 9;
/// the constant is 2 (5/4)^(2/5) (9/16)^(1/5) sqrt(pi) Gamma(7/5) / Gamma(9/10) = 2.8684).
inline constexpr double hertz_time_constant = 2.868;
/// xi_max = (5 m* v^2 / (4 rho))^(2/5), F_max = rho xi_max^(3/2), rho = 4/3 E* sqrt(R*).
inline constexpr double hertz_tolerance = 0.01;

/// Ramirez, Poeschel, Brilliantov & Schwager, PRE 60, 4465 (1999), eq. (36)-(37):
/// e(v) = 1 - C1 (3A/2) alpha^(2/5) v^(1/5) + C2 (3A/2)^2 alpha^(4/5) v^(2/5), alpha = rho/m*.
inline constexpr double ramirez_c1 = 1.15344;
inline constexpr double ramirez_c2 = 0.79826;
/// The tolerance: the two-term series itself is good to ~0.1% where we test it.
inline constexpr double ramirez_tolerance = 0.02;

// ---- rolling ---------------------------------------------------------------------------------
/// A disk sliding on a floor with friction mu starts to roll at v = 2/3 v0 after t = v0/(3 mu g);
/// a sphere at 5/7 v0 after 2 v0 / (7 mu g) (e.g. Poeschel & Schwager 2005, sec. 2.3).
inline constexpr double disk_roll_speed_ratio = 2.0 / 3.0;
inline constexpr double disk_roll_time_factor = 1.0 / 3.0;
inline constexpr double sphere_roll_speed_ratio = 5.0 / 7.0;
inline constexpr double sphere_roll_time_factor = 2.0 / 7.0;
/// 1%: the rolling point is found on a step grid of 1/1000 of the sliding time, and the floor's
/// normal spring oscillates slightly as the contact loads.
inline constexpr double rolling_tolerance = 0.01;

// ---- linear damping conventions --------------------------------------------------------------
/// Closed forms of the damped linear oscillator started at the touch with the impact speed:
/// restitution exp(-pi zeta / sqrt(1 - zeta^2)) for the classic dashpot that may pull (the
/// textbook value; Tsuji et al. 1992), closed_forms.hpp's never-attractive restitution for a cut
/// force, and the peak overlap (v / omega_0) exp(-zeta / sqrt(1 - zeta^2) atan(sqrt(1 - zeta^2) /
/// zeta)) either way (the cut acts only after it). Measured with Gear at this many steps per
/// contact: a cut force ends the contact mid-step, an error of first order in dt (0.4% of e at
/// 200 steps), which 2e-3 holds at 1000.
inline constexpr double linear_damping_steps = 1000.0;
inline constexpr double linear_damping_tolerance = 2e-3;

// ---- rolling resistance ----------------------------------------------------------------------
/// Ai et al. 2011's elastic-plastic rolling law on a flat floor. Rolling on it at the full
/// mobilisation moment mu_r R F_n, a grain of inertia I = k m R^2 decelerates at
/// mu_r g / (1 + k): 2/3 mu_r g for a disk, 5/7 mu_r g for a sphere (the torque balance about
/// the centre with friction rolling it without slip). On a slope of angle alpha it rests while
/// tan alpha <= mu_r (the moment that holds it, m g R sin alpha, is within mu_r R m g cos alpha)
/// and beyond that rolls down at g (sin alpha - mu_r cos alpha) / (1 + k).
inline constexpr double disk_inertia_factor = 0.5;
inline constexpr double sphere_inertia_factor = 0.4;
/// 1%: the floor's normal spring, on which the moment's limit rides, oscillates a little as the
/// grain's weight and the torque load it; the deceleration is measured over half the roll.
inline constexpr double rolling_resistance_tolerance = 0.01;

// ---- integrators -----------------------------------------------------------------------------
/// Velocity Verlet is second order: halving dt divides the global error by 4. The 5-value Gear
/// predictor-corrector (position and four derivatives) has a local error O(dt^5) and so a
/// global error O(dt^4) (Gear 1971, Numerical Initial Value Problems, ch. 9): halving dt
/// divides it by 16. Measured on the oscillator from 50 to 800 steps a period: 15.0 to 16.0.
inline constexpr double verlet_error_ratio = 4.0;
inline constexpr double gear_error_ratio = 16.0;
/// 10% on a ratio: the asymptotic regime is reached but not exactly.
inline constexpr double order_tolerance = 0.10;

// ---- many-particle energy conservation -------------------------------------------------------
/// Issue 2: an elastic frictionless gas of 1000 disks drifts less than 1e-4 over 1e5 steps.
inline constexpr double gas_drift_tolerance = 1.0e-4;

} // namespace talus::reference
