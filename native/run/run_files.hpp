#pragma once
// The text files a run appends to as it goes (thermo.csv, track.csv, ...), in its folder: opened
// fresh for a new run and for appending on a resume, flushed and measured at each checkpoint, so
// that a resume cuts them back to what the checkpoint counts.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>

namespace talus::run {

class RunFiles {
public:
  /// `fresh`: a new run (the files start empty); else a resume (they are appended to).
  RunFiles(std::filesystem::path dir, bool fresh) : dir_(std::move(dir)), fresh_(fresh) {}
  const std::filesystem::path& dir() const { return dir_; }
  bool fresh() const { return fresh_; }
  /// Opens `name` in the folder (once), with `header` first when it starts empty; throws
  /// WriteError when it cannot.
  std::ostream& open(const std::string& name, const std::string& header = "");
  /// Writes out what each file holds; throws WriteError naming a file that failed.
  void flush();
  /// Each open file's size now, bytes.
  std::map<std::string, std::uint64_t> sizes() const;
  /// Closes every file (after a failed write, before the outputs are cut back).
  void close();

private:
  std::filesystem::path dir_;
  bool fresh_;
  std::map<std::string, std::unique_ptr<std::ofstream>> files_;
};

} // namespace talus::run
