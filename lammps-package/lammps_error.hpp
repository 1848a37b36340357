#pragma once
// How the package stops LAMMPS with a message: Error::all with a whole std::string, the overload
// that is compiled into liblammps (see compat/fmt/format.h for why no formatting template is used).
#include <string>

#include "error.h"

namespace talus::lammps {

/// Stops the run on every rank with "STYLE: message" (LAMMPS adds the file and line).
[[noreturn]] inline void fail(LAMMPS_NS::Error* error, const std::string& style,
                              const std::string& message, const char* file, int line) {
  error->all(std::string(file), line, style + ": " + message);
}

} // namespace talus::lammps
