#pragma once
// Timestep helpers: the laws' closed forms (talus/closed_forms.hpp) and the integrators' bounds.
#include "talus/closed_forms.hpp"

namespace talus {

/// Largest stable step of velocity Verlet for an undamped oscillator of stiffness k: 2/omega.
/// (For the Gear predictor-corrector see max_stable_timestep in integrate/integrator.hpp.)
double verlet_stable_timestep(double stiffness, double m_eff);

} // namespace talus
