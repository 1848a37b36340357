// fix granthesis/history: the tangential springs of the contacts of pair_style granthesis (and
// fix granthesis/wall) with a law that keeps them (Cundall-Strack, Mindlin). Made by those
// styles, not by a deck. Each atom keeps its contacts' springs beside the partner they are with
// (an atom id, or a wall segment's number) and takes them along when it moves to another rank
// and into a restart file; the style that made it makes it again, under the same ID, after
// read_restart, and gets them back.
// The pair style computes a contact with a ghost atom on both ranks (newton_pair off), and each
// rank keeps the spring of its own atom: the spring is the same seen from either side.
// The style block lets the file drop into a LAMMPS source tree as a package (so no #pragma once).
#ifdef FIX_CLASS
// clang-format off
FixStyle(granthesis/history, talus::lammps::FixContactHistory);
// clang-format on
#else
#ifndef TALUS_LAMMPS_FIX_CONTACT_HISTORY_H
#define TALUS_LAMMPS_FIX_CONTACT_HISTORY_H
#include <source_location>
#include <string>
#include <vector>

#include "fix.h"
#include "lmptype.h"

namespace talus::lammps {

class FixContactHistory : public LAMMPS_NS::Fix {
public:
  /// fix ID group granthesis/history [slots K] [values V]: K springs at most per atom (default
  /// 16), each of V numbers (1: a 2D spring along the tangent, 3: a 3D vector; default 1).
  FixContactHistory(LAMMPS_NS::LAMMPS* instance, int narg, char** arg);
  ~FixContactHistory() override;

  /// The fix `id` of this style, made with `slots` slots if there is none yet; `owner` (a style's
  /// name) is named in the error when a fix of that ID is of another style.
  static FixContactHistory* find_or_make(LAMMPS_NS::LAMMPS* instance, const std::string& id,
                                         int slots, const std::string& owner, int values = 1);

  int setmask() override;
  void grow_arrays(int nmax) override;
  void copy_arrays(int i, int j, int delflag) override;
  void set_arrays(int i) override;
  int pack_exchange(int i, double* buffer) override;
  int unpack_exchange(int nlocal, double* buffer) override;
  int pack_restart(int i, double* buffer) override;
  void unpack_restart(int nlocal, int nth) override;
  int size_restart(int nlocal) override;
  int maxsize_restart() override;
  double memory_usage() override;

  /// A pass over the contacts starts: a contact not looked up (spring()) during it is
  /// forgotten at end_pass().
  void begin_pass() { ++pass_; }
  /// Forgets the springs of local atoms' contacts that were not looked up since begin_pass().
  void end_pass(int nlocal);
  /// The spring of atom i's contact with `partner`, 0 for a new contact; marks it as current.
  /// Stops the run, naming the atom, when the atom has more contacts than slots.
  double& spring(int i, LAMMPS_NS::tagint partner);
  /// The spring of atom i's contact with `partner`, 0 if it has none; changes nothing.
  double peek(int i, LAMMPS_NS::tagint partner) const;
  /// The V numbers of atom i's contact with `partner` (zeros for a new one), as spring() does.
  double* springs(int i, LAMMPS_NS::tagint partner) { return &spring(i, partner); }
  /// The same as peek(): nullptr where atom i has no such contact.
  const double* peek_springs(int i, LAMMPS_NS::tagint partner) const;
  int values() const { return values_; }

private:
  struct Slot {
    LAMMPS_NS::tagint partner;
    double spring[3]; ///< the first values_ in use
    unsigned pass;
  };
  /// Stops the run naming this style; LAMMPS cites the caller's file and line.
  [[noreturn]] void fail(const std::string& message,
                         std::source_location at = std::source_location::current()) const;

  int slots_ = 16;         ///< springs per atom at most
  int values_ = 1;         ///< numbers per spring
  unsigned pass_ = 0;      ///< the current pass
  std::vector<int> count_; ///< per atom: springs kept
  std::vector<Slot> slot_; ///< per atom: slots_ slots, the first count_ in use
};

} // namespace talus::lammps

#endif // TALUS_LAMMPS_FIX_CONTACT_HISTORY_H
#endif // FIX_CLASS
