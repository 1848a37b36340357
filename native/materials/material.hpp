#pragma once
// A material (talus/material.hpp), checked before a run.
#include "talus/material.hpp"

namespace talus {

/// Throws InvalidArgument naming the material, the key and the allowed range.
void validate(const Material& m);

} // namespace talus
