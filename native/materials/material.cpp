#include "materials/material.hpp"

#include "talus/error.hpp"
#include "talus/material_keys.hpp"

namespace talus {

void validate(const Material& m) {
  const std::string problem = material_key_error(m);
  require(problem.empty(), "material '" + m.name + "': " + problem);
}

} // namespace talus
