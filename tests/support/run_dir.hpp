#pragma once
// A test's run folder: under the system's temporary folder, emptied first. Its name holds the
// process id, so that two test suites running at once (two builds' ctest on one machine) do not
// empty each other's folders.
#include <filesystem>
#include <string>

#include <unistd.h>

namespace talus::testing {

inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path d = std::filesystem::temp_directory_path() /
                                  ("talus_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  return d;
}

} // namespace talus::testing
