#include "materials/material.hpp"

#include <cmath>

#include "talus/error.hpp"

namespace talus {

namespace {
void check(bool ok, const Material& m, const char* key, const std::string& allowed, double value) {
  require(ok, "material '" + m.name + "': " + key + " = " + std::to_string(value) +
                  " is out of range; allowed: " + allowed);
}
} // namespace

void validate(const Material& m) {
  check(std::isfinite(m.density) && m.density > 0.0, m, "density", "> 0 kg/m^3", m.density);
  check(std::isfinite(m.young) && m.young > 0.0, m, "young", "> 0 Pa", m.young);
  check(m.poisson >= 0.0 && m.poisson < 0.5, m, "poisson", "[0, 0.5)", m.poisson);
  check(m.restitution > 0.0 && m.restitution <= 1.0, m, "restitution", "(0, 1]", m.restitution);
  check(std::isfinite(m.friction) && m.friction >= 0.0, m, "friction", ">= 0", m.friction);
  check(m.tangential_damping >= 0.0 || m.tangential_damping == -1.0, m, "tangential_damping",
        ">= 0 1/s (or -1: from restitution)", m.tangential_damping);
  check(m.normal_stiffness >= 0.0, m, "normal_stiffness", ">= 0 N/m (0: not given)",
        m.normal_stiffness);
  check(m.tangential_stiffness_ratio > 0.0 || m.tangential_stiffness_ratio == -1.0, m,
        "tangential_stiffness_ratio", "> 0 (or -1: from poisson)", m.tangential_stiffness_ratio);
  check(m.hertz_damping >= 0.0 || m.hertz_damping == -1.0, m, "hertz_damping",
        ">= 0 s (or -1: from restitution)", m.hertz_damping);
}

} // namespace talus
