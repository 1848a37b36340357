#pragma once
// A run's CSV files (thermo.csv, stages.csv) read back by name, for the analyses that work from
// them rather than from the snapshots.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace talus::cli {

using CsvRow = std::map<std::string, std::string>;

/// The rows of a CSV file, each field under its column's name (RFC 4180 quotes). `who` names the
/// analysis in the error when the file is missing.
std::vector<CsvRow> read_csv_rows(const std::filesystem::path& file, const std::string& who);

/// The number in column `key` of a row of `file`; InvalidArgument naming the analysis, the file,
/// the column and `needs` (what a run must have for it) when it is not there.
double csv_value(const CsvRow& row, const std::string& key, const std::string& who,
                 const std::string& file, const std::string& needs);

} // namespace talus::cli
