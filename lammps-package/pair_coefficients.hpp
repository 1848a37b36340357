#pragma once
// The coefficients of `pair_coeff I J key value ...` for pair_style granthesis: the material keys
// of the native scenarios (src/talus/material_keys.hpp), with the same defaults, ranges and
// units. Independent of LAMMPS, so that it is tested on its own.
#include <optional>
#include <string>
#include <vector>

#include "talus/material.hpp"

namespace talus::lammps {

/// The material that `words` (key value key value ...) describe, every other key at its native
/// default. Throws InvalidArgument naming the key and its allowed values for an unknown key, a
/// key without a value, a value that is not a finite number, one outside its range, or
/// `density` (set per atom in LAMMPS: `set type N density/disc RHO`).
Material parse_pair_coefficients(const std::vector<std::string>& words);

/// The finite number that `text` is, all of it; nothing for anything else (an empty text, trailing
/// characters, inf, nan).
std::optional<double> finite_number(const std::string& text);

/// "young, poisson, ...": the keys pair_coeff accepts.
std::string pair_coefficient_names();

} // namespace talus::lammps
