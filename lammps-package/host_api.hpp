#pragma once
// The calls in which the pair style's two hosts differ: LAMMPS (29 Sep 2021, the default) and
// LIGGGHTS 3.8 (TALUS_HOST_LIGGGHTS), whose API is LAMMPS' of about 2012. Everything else the
// styles use is common to both. Errors pass whole std::strings: LAMMPS' formatting templates are
// not compiled into Debian's liblammps (see compat/fmt/format.h).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <source_location>
#include <string>

#include "error.h"
#include "force.h"
#include "lammps.h"
#include "pair.h"
#include "talus/law_table.hpp"
#ifndef TALUS_HOST_LIGGGHTS
#include "atom.h"
#include "fix.h"
#include "fix_contact_history.h"
#include "modify.h"
#include "utils.h"
#endif

namespace talus::lammps {

/// Stops the run on every rank with "STYLE: message"; the host adds the file and line of `at`,
/// the place that found the problem (a style's fail() passes on its caller's).
[[noreturn]] inline void fail(LAMMPS_NS::Error* error, const std::string& style,
                              const std::string& message,
                              std::source_location at = std::source_location::current()) {
  const int line = static_cast<int>(at.line());
#ifdef TALUS_HOST_LIGGGHTS
  error->all(at.file_name(), line, (style + ": " + message).c_str());
  std::abort(); // LIGGGHTS' Error::all ends the process but is not declared so
#else
  error->all(std::string(at.file_name()), line, style + ": " + message);
#endif
}

inline void warn(LAMMPS_NS::Error* error, const std::string& message,
                 std::source_location at = std::source_location::current()) {
  const int line = static_cast<int>(at.line());
#ifdef TALUS_HOST_LIGGGHTS
  error->warning(at.file_name(), line, message.c_str());
#else
  error->warning(std::string(at.file_name()), line, message);
#endif
}

/// Why a deck's `units` cannot be used (empty for units si): every value the styles read or
/// default to is in SI units, and none is converted.
inline std::string units_problem(const char* unit_style) {
  const std::string units = unit_style;
  if (units == "si") return {};
  return "units " + units +
         ": every value of the talus styles and every default is in SI units (m, kg, s, N, Pa, "
         "J), and none is converted; allowed: units si";
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
    fail(lmp->error, "restart", "the file ends early");
#else
  LAMMPS_NS::utils::sfread(__FILE__, __LINE__, to, size, count, file, nullptr, lmp->error);
#endif
}

#ifdef TALUS_HOST_LIGGGHTS
/// LIGGGHTS keeps no spring per contact for this pair style (its own history lives in its
/// granular framework): a law with a spring is refused there, so this stand-in for
/// fix granthesis/history is never made and its calls are never reached.
class FixContactHistory {
public:
  void begin_pass() {}
  void end_pass(int) {}
  double& spring(int, LAMMPS_NS::tagint) { return unused_[0]; }
  double* springs(int, LAMMPS_NS::tagint) { return unused_; }
  double peek(int, LAMMPS_NS::tagint) const { return 0.0; }
  const double* peek_springs(int, LAMMPS_NS::tagint) const { return nullptr; }

private:
  double unused_[3] = {};
};
inline constexpr bool host_keeps_springs = false;
#else
inline constexpr bool host_keeps_springs = true;
#endif

/// The tangential laws the host can run: every one, or in LIGGGHTS those without a spring.
inline std::string host_tangential_law_names() {
  return host_keeps_springs ? law_names<TangentialLaw>() : history_free_tangential_names();
}

/// LAMMPS' Pair with the members whose form differs between the hosts: the restart readers'
/// signatures, the start of the energy and virial tally, the reach, and the springs' fix.
class HostPair : public LAMMPS_NS::Pair {
public:
  explicit HostPair(LAMMPS_NS::LAMMPS* instance) : Pair(instance) {
#ifndef TALUS_HOST_LIGGGHTS
    finitecutflag = 1; // LIGGGHTS' neighbour lists add the skin to init_one's reach anyway
#endif
  }
#ifdef TALUS_HOST_LIGGGHTS
  void read_restart(FILE* file, int, int) override {
    read_coefficients(file);
  }
  void read_restart_settings(FILE* file, int, int) override {
    read_settings(file);
  }
#else
  void read_restart(FILE* file) override {
    read_coefficients(file);
  }
  void read_restart_settings(FILE* file) override {
    read_settings(file);
  }
#endif

protected:
  virtual void read_settings(FILE* file) = 0;     ///< the style's settings, from a restart file
  virtual void read_coefficients(FILE* file) = 0; ///< its coefficients, from a restart file

  /// The start of a force pass: the energy and virial tallies this pass asks for.
  void start_tally(int eflag, int vflag) {
#ifdef TALUS_HOST_LIGGGHTS
    if (eflag || vflag)
      ev_setup(eflag, vflag);
    else
      evflag = vflag_fdotr = 0;
#else
    ev_init(eflag, vflag);
#endif
  }

  /// The fix `id` that keeps the springs (slots per atom, `values` numbers each), found or made;
  /// in a host that keeps none, the run stops (`style` names the asker).
  FixContactHistory* springs_fix(const std::string& id, int slots, const std::string& style,
                                 int values = 1) {
#ifdef TALUS_HOST_LIGGGHTS
    (void)id;
    (void)slots;
    (void)values;
    fail(error, style, "a law with a contact history is not available in LIGGGHTS");
#else
    return FixContactHistory::find_or_make(lmp, id, slots, style, values);
#endif
  }

  /// The largest radius that a `fix pour` or `fix deposit` of the deck will insert (m; 0 if none,
  /// and always in LIGGGHTS, whose insertion fixes differ): the pair's reach must cover grains
  /// that are not there yet. Read through each fix's extract("radius", type), as LAMMPS' own
  /// granular styles read it.
  double inserted_radius_max() const {
    double largest = 0.0;
#ifndef TALUS_HOST_LIGGGHTS
    for (int k = 0; k < modify->nfix; ++k) {
      const std::string style = modify->fix[k]->style;
      if (style != "pour" && style != "deposit") continue;
      for (int type = 1; type <= atom->ntypes; ++type) {
        int asked = type;
        if (const auto* r = static_cast<const double*>(modify->fix[k]->extract("radius", asked)))
          largest = std::max(largest, *r);
      }
    }
#endif
    return largest;
  }

  /// Deletes the springs' fix `id`, if it is still there.
  void remove_springs_fix(const std::string& id) {
#ifndef TALUS_HOST_LIGGGHTS
    if (modify->find_fix(id.c_str()) >= 0) modify->delete_fix(id.c_str());
#else
    (void)id;
#endif
  }
};

/// Writes a fix's global state into a restart file, as the host reads it back for the fix's
/// restart(): the size in bytes, then the values. Call on rank 0 only.
inline void write_fix_state(FILE* file, const double* values, std::size_t count) {
  const int size = static_cast<int>(count * sizeof(double));
  std::fwrite(&size, sizeof(int), 1, file);
  std::fwrite(values, sizeof(double), count, file);
}

} // namespace talus::lammps
