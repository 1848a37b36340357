#pragma once
// A LAMMPS (or, with TALUS_HOST_LIGGGHTS, a LIGGGHTS) instance in the test process, with the talus
// styles registered: commands go in one at a time, and the atoms' arrays are read directly. LAMMPS
// stops a bad command by throwing (Debian builds it with exceptions), which the tests catch as
// std::exception.
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "atom.h"
#include "input.h"
#include "lammps.h"
#include "register.hpp"

namespace talus::lammps_test {

class LammpsInstance {
public:
  /// registered = false: a bare LAMMPS, for styles registered another way (the plugin test)
  explicit LammpsInstance(bool registered = true) {
    std::vector<std::string> words{"talus-tests", "-log", "none", "-screen", "none"};
#ifndef TALUS_HOST_LIGGGHTS
    words.emplace_back("-nocite"); // LIGGGHTS has no such option
#endif
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    lmp_ = new LAMMPS_NS::LAMMPS(static_cast<int>(argv.size()), argv.data(), MPI_COMM_WORLD);
    if (registered) talus_lammps_register(lmp_);
  }
  ~LammpsInstance() {
    delete lmp_;
  }
  LammpsInstance(const LammpsInstance&) = delete;
  LammpsInstance& operator=(const LammpsInstance&) = delete;

  void command(const std::string& line) {
    lmp_->input->one(line.c_str());
  }
  void commands(const std::vector<std::string>& lines) {
    for (const std::string& l : lines) command(l);
  }
  LAMMPS_NS::LAMMPS* lmp() {
    return lmp_;
  }
  /// The local index of the atom with this tag (needs atom_modify map array).
  int index(int tag) {
    return lmp_->atom->map(tag);
  }
  double* force(int tag) {
    return lmp_->atom->f[index(tag)];
  }
  double* torque(int tag) {
    return lmp_->atom->torque[index(tag)];
  }
  double* position(int tag) {
    return lmp_->atom->x[index(tag)];
  }
  double* velocity(int tag) {
    return lmp_->atom->v[index(tag)];
  }

private:
  LAMMPS_NS::LAMMPS* lmp_ = nullptr;
};

/// A number as LAMMPS must read it to get the same double: 17 significant digits.
inline std::string exact(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

/// Runs a deck in talus-lmp, the package's launcher (TALUS_LMP), in a process of its own (Debian's
/// LAMMPS ends the process on an error: Error::all does not throw there): what it printed, and
/// its exit status in `status`.
inline std::string run_deck(const std::vector<std::string>& deck, int& status) {
  // a file per process: ctest runs the tests side by side
  const std::string path = testing::TempDir() + "talus_deck_" + std::to_string(getpid()) + ".in";
  {
    std::ofstream out(path);
    for (const std::string& line : deck) out << line << "\n";
  }
  std::string command(TALUS_LMP);
  command.append(" -in ").append(path).append(" -log none 2>&1");
  std::string printed;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) {
    status = -1;
    return "popen failed";
  }
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) printed.append(buffer);
  status = pclose(pipe);
  return printed;
}

/// A deck of two disks of types 1 and 2, touching, in a 2d box in SI units; then `lines`.
inline std::vector<std::string> two_type_deck(const std::vector<std::string>& lines) {
  std::vector<std::string> deck{"dimension 2",
                                "units si",
                                "atom_style sphere",
                                "boundary f f p",
                                "comm_modify vel yes",
                                "region box block -1 1 -1 1 -0.01 0.01",
                                "create_box 2 box",
                                "create_atoms 1 single 0 0 0",
                                "create_atoms 2 single 0.009 0 0",
                                "set atom * diameter 0.01",
                                "set atom * density/disc 2650"};
  deck.insert(deck.end(), lines.begin(), lines.end());
  return deck;
}

/// Expects a deck to stop with an error whose text contains `expected`; returns what it printed.
inline std::string expect_deck_error(const std::vector<std::string>& deck,
                                     const std::string& expected) {
  int status = 0;
  const std::string printed = run_deck(deck, status);
  EXPECT_NE(status, 0) << printed;
  EXPECT_NE(printed.find("ERROR"), std::string::npos) << printed;
  EXPECT_NE(printed.find(expected), std::string::npos) << "expected: " << expected << "\n"
                                                       << printed;
  return printed;
}

/// Expects a deck to run to its end with a warning whose text contains `expected`.
inline void expect_deck_warning(const std::vector<std::string>& deck, const std::string& expected) {
  int status = 0;
  const std::string printed = run_deck(deck, status);
  EXPECT_EQ(status, 0) << printed;
  const std::size_t at = printed.find("WARNING");
  ASSERT_NE(at, std::string::npos) << printed;
  EXPECT_NE(printed.find(expected, at), std::string::npos) << "expected: " << expected << "\n"
                                                           << printed;
}

} // namespace talus::lammps_test
