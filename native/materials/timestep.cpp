#include "materials/timestep.hpp"

#include <cmath>

namespace talus {

double verlet_stable_timestep(double stiffness, double m_eff) {
  return 2.0 / std::sqrt(stiffness / m_eff);
}

} // namespace talus
