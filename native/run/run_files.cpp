#include "run/run_files.hpp"

#include "io/checkpoint.hpp"

namespace fs = std::filesystem;

namespace talus::run {

std::ostream& RunFiles::open(const std::string& name, const std::string& header) {
  auto& f = files_[name];
  if (f) return *f;
  const auto mode = fresh_ ? std::ios::out | std::ios::trunc : std::ios::out | std::ios::app;
  std::error_code ec;
  const bool empty = fresh_ || !fs::exists(dir_ / name, ec) || fs::file_size(dir_ / name, ec) == 0;
  f = std::make_unique<std::ofstream>(dir_ / name, mode);
  if (!*f) throw WriteError("cannot write " + (dir_ / name).string());
  if (empty) *f << header;
  return *f;
}

void RunFiles::flush() {
  for (auto& [name, f] : files_) {
    f->flush();
    if (f->is_open() && !*f) throw WriteError("cannot write " + (dir_ / name).string());
  }
}

std::map<std::string, std::uint64_t> RunFiles::sizes() const {
  std::map<std::string, std::uint64_t> bytes;
  for (const auto& [name, f] : files_)
    if (fs::exists(dir_ / name)) bytes[name] = fs::file_size(dir_ / name);
  return bytes;
}

void RunFiles::close() {
  for (auto& [name, f] : files_) f->close();
}

} // namespace talus::run
