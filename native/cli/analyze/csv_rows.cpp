#include "cli/analyze/csv_rows.hpp"

#include <sstream>

#include "io/checkpoint.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

// The fields of a CSV line, double quotes around a field that holds commas ("" is a quote).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (c == '"' && quoted && k + 1 < line.size() && line[k + 1] == '"')
      out.back() += '"', ++k;
    else if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

} // namespace

std::vector<CsvRow> read_csv_rows(const fs::path& file, const std::string& who) {
  if (!fs::exists(file)) throw InvalidArgument(who + ": " + file.string() + " is missing");
  std::istringstream in(read_file(file.string()));
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = csv_fields(line);
  std::vector<CsvRow> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> f = csv_fields(line);
    auto& row = rows.emplace_back();
    for (std::size_t k = 0; k < header.size() && k < f.size(); ++k) row[header[k]] = f[k];
  }
  return rows;
}

double csv_value(const CsvRow& row, const std::string& key, const std::string& who,
                 const std::string& file, const std::string& needs) {
  const auto it = row.find(key);
  if (it == row.end())
    throw InvalidArgument(who + ": " + file + " has no column '" + key + "' (" + needs + ")");
  return std::stod(it->second);
}

} // namespace talus::cli
