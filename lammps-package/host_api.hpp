#pragma once
// The calls in which the pair style's two hosts differ: LAMMPS (29 Sep 2021, the default) and
// LIGGGHTS 3.8 (TALUS_HOST_LIGGGHTS), whose API is LAMMPS' of about 2012. Everything else the
// styles use is common to both. Errors pass whole std::strings: LAMMPS' formatting templates are
// not compiled into Debian's liblammps (see compat/fmt/format.h).
#include <cstdio>
#include <cstdlib>
#include <string>

#include "error.h"
#include "force.h"
#include "lammps.h"
#ifndef TALUS_HOST_LIGGGHTS
#include "utils.h"
#endif

namespace talus::lammps {

/// Stops the run on every rank with "STYLE: message" (the host adds the file and line).
[[noreturn]] inline void fail(LAMMPS_NS::Error* error, const std::string& style,
                              const std::string& message, const char* file, int line) {
#ifdef TALUS_HOST_LIGGGHTS
  error->all(file, line, (style + ": " + message).c_str());
  std::abort(); // LIGGGHTS' Error::all ends the process but is not declared so
#else
  error->all(std::string(file), line, style + ": " + message);
#endif
}

inline void warn(LAMMPS_NS::Error* error, const std::string& message, const char* file, int line) {
#ifdef TALUS_HOST_LIGGGHTS
  error->warning(file, line, message.c_str());
#else
  error->warning(std::string(file), line, message);
#endif
}

/// The types a pair_coeff argument names ("2", "*", "1*3"): [lo, hi] within 1..ntypes.
inline void type_bounds(LAMMPS_NS::LAMMPS* lmp, char* text, int ntypes, int& lo, int& hi) {
#ifdef TALUS_HOST_LIGGGHTS
  lmp->force->bounds(text, ntypes, lo, hi);
#else
  LAMMPS_NS::utils::bounds(__FILE__, __LINE__, text, 1, ntypes, lo, hi, lmp->error);
#endif
}

/// Reads `count` items of `size` bytes from a restart file on rank 0, or stops the run.
inline void read_restart_items(LAMMPS_NS::LAMMPS* lmp, void* to, std::size_t size,
                               std::size_t count, FILE* file) {
#ifdef TALUS_HOST_LIGGGHTS
  if (std::fread(to, size, count, file) != count)
    fail(lmp->error, "restart", "the file ends early", __FILE__, __LINE__);
#else
  LAMMPS_NS::utils::sfread(__FILE__, __LINE__, to, size, count, file, nullptr, lmp->error);
#endif
}

/// Writes a fix's global state into a restart file, as the host reads it back for the fix's
/// restart(): the size in bytes, then the values. Call on rank 0 only.
inline void write_fix_state(FILE* file, const double* values, std::size_t count) {
  const int size = static_cast<int>(count * sizeof(double));
  std::fwrite(&size, sizeof(int), 1, file);
  std::fwrite(values, sizeof(double), count, file);
}

} // namespace talus::lammps
