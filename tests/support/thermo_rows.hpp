#pragma once
// A run folder's thermo.csv read back by column name.
#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "io/checkpoint.hpp"

namespace talus::testing {

/// The last row of dir/thermo.csv, each value under its column's name.
inline std::map<std::string, double> last_thermo_row(const std::filesystem::path& dir) {
  std::istringstream thermo(read_file((dir / "thermo.csv").string()));
  std::string header, row, line;
  std::getline(thermo, header);
  while (std::getline(thermo, line)) row = line;
  std::istringstream h(header), r(row);
  std::map<std::string, double> last;
  for (std::string name, value; std::getline(h, name, ',') && std::getline(r, value, ',');)
    last[name] = std::stod(value);
  return last;
}

} // namespace talus::testing
