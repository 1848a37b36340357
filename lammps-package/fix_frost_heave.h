// fix frost/heave: the thesis' freeze (chapter 5.2.1) in LAMMPS. When the group's kinetic energy
// falls below epsilon, every atom of the group has its height above the permafrost table
// multiplied by the heave factor, and the neighbour lists are rebuilt before the next forces.
// Syntax and conventions: lammps-package/README.md.
// The style block lets the file drop into a LAMMPS source tree as a package: LAMMPS includes
// its style headers once to declare the classes and once with FIX_CLASS defined to
// register them (so no #pragma once here).
#ifdef FIX_CLASS
// clang-format off
FixStyle(frost/heave, talus::lammps::FixFrostHeave);
// clang-format on
#else
#ifndef TALUS_LAMMPS_FIX_FROST_HEAVE_H
#define TALUS_LAMMPS_FIX_FROST_HEAVE_H
#include <source_location>
#include <string>

#include "fix.h"
#include "run_clock.hpp"

namespace talus::lammps {

class FixFrostHeave : public LAMMPS_NS::Fix {
public:
  FixFrostHeave(LAMMPS_NS::LAMMPS* instance, int narg, char** arg);

  int setmask() override;
  void init() override;
  void setup(int vflag) override;
  void end_of_step() override;
  double compute_scalar() override;
  double compute_vector(int n) override;
  void write_restart(FILE* file) override;
  void restart(char* buffer) override;

private:
  /// Stops the run naming this style; LAMMPS cites the caller's file and line.
  [[noreturn]] void fail(const std::string& message,
                         std::source_location at = std::source_location::current()) const;
  double group_kinetic_energy() const;
  void heave();
  double now() const; ///< s: the simulation time, carried across restart files

  double epsilon_ = 0.0;    ///< J: the kinetic energy below which the group is at rest
  double factor_ = 1.0;     ///< delta_H: the heights above the table are multiplied by it
  double table_ = 0.0;      ///< m: the permafrost table's height (y in 2d, z in 3d)
  double interval_ = 0.0;   ///< s: the shortest time between two heaves
  bool disc_ = true;        ///< the moment of inertia of a disk (1/2 m r^2), else of a sphere
  double cycles_ = 0.0;     ///< heaves so far (a double: thermo and restart files take doubles)
  double last_time_ = -1.0; ///< s: the time of the last heave, -1 before the first
  double kinetic_ = 0.0;    ///< J: the group's kinetic energy at the last test
  LAMMPS_NS::bigint last_step_ = -1; ///< the step of the last heave (or of the fix's definition
                                     ///< with initial_wait yes), -1 before the first
  RunClock clock_;
};

} // namespace talus::lammps

#endif // TALUS_LAMMPS_FIX_FROST_HEAVE_H
#endif // FIX_CLASS
