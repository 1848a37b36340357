#pragma once
// A test's run folder: under the system's temporary folder, emptied first.
#include <filesystem>
#include <string>

namespace talus::testing {

inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path d = std::filesystem::temp_directory_path() / ("talus_test_" + name);
  std::filesystem::remove_all(d);
  return d;
}

} // namespace talus::testing
