#include "run/run_files.hpp"

#include <cerrno>
#include <cstring>

#include <fmt/core.h>
#include <sys/resource.h>

#include "io/checkpoint.hpp"

namespace fs = std::filesystem;

namespace talus::run {

namespace {

// Why a write to `file` failed. A stream keeps no errno of its own, and the failed write may
// lie buffered behind later ones, so the likely causes are looked at now: the file size limit,
// the free space, and errno if still set.
std::string failure_reason(const fs::path& file, int error) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  rlimit limit{};
  if (!ec && ::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
      size + 65536 >= limit.rlim_cur)
    return fmt::format("{} (the file holds {} bytes; this process's file size limit, ulimit -f, "
                       "is {} bytes)",
                       std::strerror(EFBIG), size, static_cast<std::uintmax_t>(limit.rlim_cur));
  const fs::space_info space = fs::space(file.parent_path(), ec);
  if (!ec && space.available < 65536)
    return fmt::format("{} ({} bytes free on its file system)", std::strerror(ENOSPC),
                       space.available);
  return error != 0 ? std::string(std::strerror(error)) : std::string("the system gave no reason");
}

[[noreturn]] void cannot_write(const fs::path& file) {
  const int error = errno;
  throw WriteError("cannot write " + file.string() + ": " + failure_reason(file, error), error);
}

} // namespace

std::ostream& RunFiles::open(const std::string& name, const std::string& header) {
  auto& f = files_[name];
  if (f) return *f;
  const auto mode = fresh_ ? std::ios::out | std::ios::trunc : std::ios::out | std::ios::app;
  std::error_code ec;
  const bool empty = fresh_ || !fs::exists(dir_ / name, ec) || fs::file_size(dir_ / name, ec) == 0;
  errno = 0;
  f = std::make_unique<std::ofstream>(dir_ / name, mode);
  if (!*f) cannot_write(dir_ / name);
  if (empty) *f << header;
  return *f;
}

void RunFiles::flush() {
  for (auto& [name, f] : files_) {
    errno = 0;
    f->flush();
    if (f->is_open() && !*f) cannot_write(dir_ / name);
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
