#pragma once
// A run folder's thermo.csv read back by column name.
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/checkpoint.hpp"

namespace talus::testing {

/// Every row of dir/thermo.csv, each value under its column's name.
inline std::vector<std::map<std::string, double>> thermo_rows(const std::filesystem::path& dir) {
  std::istringstream thermo(read_file((dir / "thermo.csv").string()));
  std::string header, line;
  std::getline(thermo, header);
  std::vector<std::map<std::string, double>> rows;
  while (std::getline(thermo, line)) {
    std::istringstream h(header), r(line);
    std::map<std::string, double>& row = rows.emplace_back();
    for (std::string name, value; std::getline(h, name, ',') && std::getline(r, value, ',');)
      row[name] = std::stod(value);
  }
  return rows;
}

/// The last row of dir/thermo.csv, each value under its column's name.
inline std::map<std::string, double> last_thermo_row(const std::filesystem::path& dir) {
  const auto rows = thermo_rows(dir);
  return rows.empty() ? std::map<std::string, double>{} : rows.back();
}

/// The mean of a column over the rows with from <= time < to (0 without such rows).
inline double mean_of(const std::vector<std::map<std::string, double>>& rows,
                      const std::string& column, double from,
                      double to = std::numeric_limits<double>::infinity()) {
  double sum = 0.0;
  int n = 0;
  for (const auto& row : rows)
    if (row.at("time") >= from && row.at("time") < to) sum += row.at(column), ++n;
  return n > 0 ? sum / n : 0.0;
}

} // namespace talus::testing
