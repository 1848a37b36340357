#pragma once
// The keys that describe a material, with their defaults and allowed ranges: one table for every
// front end that reads materials (the native scenario loader, LAMMPS' pair_coeff), so that a
// material means the same in both. A default-made Material takes these defaults.
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <string_view>

#include "talus/material.hpp"

namespace talus {

struct MaterialKey {
  std::string_view name;
  double Material::*field;
  double fallback; ///< the value when the key is not given
  double lowest, highest;
  std::string_view allowed;       ///< the range and unit, for error messages
  bool minus_one_derives = false; ///< -1 is also allowed: derive the value (see `allowed`)
};

/// Whether x is an allowed value of key k.
constexpr bool allowed_value(const MaterialKey& k, double x) {
  return (x >= k.lowest && x <= k.highest) || (k.minus_one_derives && x == -1.0);
}

inline constexpr double no_limit = std::numeric_limits<double>::infinity();

inline constexpr std::array<MaterialKey, 13> material_keys{{
    {"density", &Material::density, 2650.0, 1e-12, no_limit, "> 0 kg/m^3"},
    {"young", &Material::young, 1.0e8, 1e-12, no_limit, "> 0 Pa"},
    {"poisson", &Material::poisson, 0.3, 0.0, 0.4999, "[0, 0.5)"},
    {"restitution", &Material::restitution, 0.5, 1e-12, 1.0, "(0, 1]"},
    {"friction", &Material::friction, 0.5, 0.0, no_limit, ">= 0"},
    {"tangential_damping", &Material::tangential_damping, 0.0, 0.0, no_limit,
     ">= 0 1/s (or -1: from restitution, Tsuji et al. 1992; spring laws only)", true},
    {"normal_stiffness", &Material::normal_stiffness, 1.0e5, 1e-12, no_limit, "> 0 N/m"},
    {"tangential_stiffness_ratio", &Material::tangential_stiffness_ratio, -1.0, 1e-12, no_limit,
     "> 0 (or -1: Mindlin's 2 (1 - nu) / (2 - nu) from poisson)", true},
    {"normal_damping_rate", &Material::normal_damping_rate, -1.0, 0.0, no_limit,
     ">= 0 1/s (or -1: from restitution)", true},
    {"hertz_damping", &Material::hertz_damping, -1.0, 0.0, no_limit,
     ">= 0 s (or -1: from restitution at simulation.impact_speed)", true},
    {"rolling_friction", &Material::rolling_friction, 0.0, 0.0, no_limit,
     ">= 0 (0: no rolling resistance)"},
    {"rolling_stiffness_factor", &Material::rolling_stiffness_factor, 2.25, 1e-12, no_limit,
     "> 0 (k_r = this x k_n mu_r^2 R*^2)"},
    {"rolling_damping", &Material::rolling_damping, 0.3, 0.0, no_limit,
     ">= 0 (the rolling dashpot over its critical value)"},
}};

inline Material::Material() {
  for (const MaterialKey& k : material_keys) this->*k.field = k.fallback;
}

/// "" if every key of m is finite and allowed, else what is wrong: the key, its value and the
/// allowed values.
inline std::string material_key_error(const Material& m) {
  for (const MaterialKey& k : material_keys) {
    const double x = m.*k.field;
    if (std::isfinite(x) && allowed_value(k, x)) continue;
    char value[32];
    std::snprintf(value, sizeof value, "%g", x);
    return std::string(k.name) + " = " + value +
           " is out of range; allowed: " + std::string(k.allowed);
  }
  return "";
}

/// "young 1e8 poisson 0.3 ...": every key but density with its value to 17 digits (read back
/// to the same double), as LAMMPS' `pair_coeff I J` for pair_style granthesis takes them.
inline std::string pair_coefficient_words(const Material& m) {
  std::string out;
  for (const MaterialKey& k : material_keys) {
    if (k.name == "density") continue;
    char value[32];
    std::snprintf(value, sizeof value, "%.17g", m.*k.field);
    out.append(out.empty() ? "" : " ").append(k.name).append(" ").append(value);
  }
  return out;
}

} // namespace talus
