#include "fix_contact_history.h"

#include <algorithm>
#include <string>

#include "atom.h"
#include "error.h"
#include "host_api.hpp"
#include "modify.h"
#include "pair_coefficients.hpp"

namespace talus::lammps {

namespace {

constexpr const char* style_name = "fix granthesis/history";

} // namespace

FixContactHistory::FixContactHistory(LAMMPS_NS::LAMMPS* instance, int narg, char** arg)
    : Fix(instance, narg, arg) {
  if (narg != 3 && narg != 5 && narg != 7)
    fail("usage: fix ID GROUP granthesis/history [slots K] [values V] (pair_style granthesis "
         "and fix granthesis/wall make it themselves)");
  for (int a = 3; a + 1 < narg; a += 2) {
    const std::string key = arg[a];
    const std::optional<double> k = finite_number(arg[a + 1]);
    if (key == "slots" && k && *k >= 1.0 && *k <= 1000.0 && *k == int(*k))
      slots_ = static_cast<int>(*k);
    else if (key == "values" && k && (*k == 1.0 || *k == 3.0))
      values_ = static_cast<int>(*k);
    else
      fail(key + " = " + arg[a + 1] +
           "; allowed: slots, a whole number from 1 to 1000; values, 1 (2d) or 3 (3d)");
  }
  create_attribute = 1;
  maxexchange = 1 + (1 + values_) * slots_;
  restart_peratom = 1;
  grow_arrays(atom->nmax); // no springs yet for any atom
  atom->add_callback(LAMMPS_NS::Atom::GROW);
  atom->add_callback(LAMMPS_NS::Atom::RESTART);
}

FixContactHistory* FixContactHistory::find_or_make(LAMMPS_NS::LAMMPS* instance,
                                                   const std::string& id, int slots,
                                                   const std::string& owner, int values) {
  LAMMPS_NS::Modify* modify = instance->modify;
  if (modify->find_fix(id) < 0)
    modify->add_fix(id + " all granthesis/history slots " + std::to_string(slots) + " values " +
                    std::to_string(values));
  auto* fix = dynamic_cast<FixContactHistory*>(modify->fix[modify->find_fix(id)]);
  if (!fix) talus::lammps::fail(instance->error, owner, "fix " + id + " is not granthesis/history");
  if (fix->values() != values)
    talus::lammps::fail(instance->error, owner,
                        "fix " + id + " keeps springs of " + std::to_string(fix->values()) +
                            " numbers, and this run's dimension needs " + std::to_string(values) +
                            " (a restart file of another dimension)");
  return fix;
}

FixContactHistory::~FixContactHistory() {
  atom->delete_callback(id, LAMMPS_NS::Atom::GROW);
  atom->delete_callback(id, LAMMPS_NS::Atom::RESTART);
}

void FixContactHistory::fail(const std::string& message, std::source_location at) const {
  talus::lammps::fail(error, style_name, message, at);
}

int FixContactHistory::setmask() {
  return 0; // nothing to do at any stage of a step: the owners call begin_pass and end_pass
}

void FixContactHistory::grow_arrays(int nmax) {
  const auto n = static_cast<std::size_t>(std::max(nmax, 1));
  count_.resize(n, 0);
  slot_.resize(n * static_cast<std::size_t>(slots_));
}

void FixContactHistory::copy_arrays(int i, int j, int /*delflag*/) {
  const auto k = static_cast<std::size_t>(slots_);
  count_[static_cast<std::size_t>(j)] = count_[static_cast<std::size_t>(i)];
  std::copy_n(slot_.begin() + static_cast<std::ptrdiff_t>(k * static_cast<std::size_t>(i)),
              count_[static_cast<std::size_t>(i)],
              slot_.begin() + static_cast<std::ptrdiff_t>(k * static_cast<std::size_t>(j)));
}

void FixContactHistory::set_arrays(int i) {
  count_[static_cast<std::size_t>(i)] = 0;
}

// count, then (partner, the spring's values) per contact; the partner as an integer in a
// double's bits
int FixContactHistory::pack_exchange(int i, double* buffer) {
  const int n = count_[static_cast<std::size_t>(i)];
  const Slot* s = &slot_[static_cast<std::size_t>(slots_) * static_cast<std::size_t>(i)];
  buffer[0] = n;
  double* out = buffer + 1;
  for (int k = 0; k < n; ++k) {
    *out++ = LAMMPS_NS::ubuf(static_cast<int64_t>(s[k].partner)).d;
    for (int v = 0; v < values_; ++v) *out++ = s[k].spring[v];
  }
  return static_cast<int>(out - buffer);
}

int FixContactHistory::unpack_exchange(int nlocal, double* buffer) {
  const int n = static_cast<int>(buffer[0]);
  count_[static_cast<std::size_t>(nlocal)] = n;
  Slot* s = &slot_[static_cast<std::size_t>(slots_) * static_cast<std::size_t>(nlocal)];
  const double* in = buffer + 1;
  for (int k = 0; k < n; ++k) {
    s[k] = {static_cast<LAMMPS_NS::tagint>(LAMMPS_NS::ubuf(*in++).i), {0.0, 0.0, 0.0}, pass_};
    for (int v = 0; v < values_; ++v) s[k].spring[v] = *in++;
  }
  return static_cast<int>(in - buffer);
}

// As pack_exchange, after the size of the whole (counted in): restart files hold every fix's
// values for an atom one after another, and each fix finds its own by skipping the others'.
int FixContactHistory::pack_restart(int i, double* buffer) {
  const int n = pack_exchange(i, buffer + 1);
  buffer[0] = 1 + n;
  return 1 + n;
}

void FixContactHistory::unpack_restart(int nlocal, int nth) {
  double* values = atom->extra[nlocal];
  std::size_t m = 0;
  for (int k = 0; k < nth; ++k) m += static_cast<std::size_t>(values[m]);
  const int n = static_cast<int>(values[m + 1]);
  if (n > slots_)
    fail("atom " + std::to_string(atom->tag[nlocal]) + " had " + std::to_string(n) +
         " springs in the restart file, more than the " + std::to_string(slots_) +
         " slots now; allowed: history_slots at least as many as when it was written");
  unpack_exchange(nlocal, values + m + 1);
}

int FixContactHistory::size_restart(int nlocal) {
  return 2 + (1 + values_) * count_[static_cast<std::size_t>(nlocal)];
}

int FixContactHistory::maxsize_restart() {
  return 2 + (1 + values_) * slots_;
}

double FixContactHistory::memory_usage() {
  return static_cast<double>(count_.capacity() * sizeof(int) + slot_.capacity() * sizeof(Slot));
}

void FixContactHistory::end_pass(int nlocal) {
  const auto k = static_cast<std::size_t>(slots_);
  for (int i = 0; i < nlocal; ++i) {
    Slot* s = &slot_[k * static_cast<std::size_t>(i)];
    int& n = count_[static_cast<std::size_t>(i)];
    n = static_cast<int>(std::remove_if(s, s + n, [&](const Slot& x) { return x.pass != pass_; }) -
                         s);
  }
}

double& FixContactHistory::spring(int i, LAMMPS_NS::tagint partner) {
  Slot* s = &slot_[static_cast<std::size_t>(slots_) * static_cast<std::size_t>(i)];
  int& n = count_[static_cast<std::size_t>(i)];
  for (int k = 0; k < n; ++k)
    if (s[k].partner == partner) {
      s[k].pass = pass_;
      return s[k].spring[0];
    }
  if (n == slots_)
    fail("atom " + std::to_string(atom->tag[i]) + " touches more than " + std::to_string(slots_) +
         " others at once; give the pair style more: pair_style granthesis NORMAL TANGENTIAL "
         "history_slots K");
  s[n] = {partner, {0.0, 0.0, 0.0}, pass_};
  return s[n++].spring[0];
}

const double* FixContactHistory::peek_springs(int i, LAMMPS_NS::tagint partner) const {
  const Slot* s = &slot_[static_cast<std::size_t>(slots_) * static_cast<std::size_t>(i)];
  for (int k = 0; k < count_[static_cast<std::size_t>(i)]; ++k)
    if (s[k].partner == partner) return s[k].spring;
  return nullptr;
}

double FixContactHistory::peek(int i, LAMMPS_NS::tagint partner) const {
  const double* s = peek_springs(i, partner);
  return s ? s[0] : 0.0;
}

} // namespace talus::lammps
