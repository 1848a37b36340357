#include "cli/run/run_folder.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/checkpoint.hpp"
#include "scenario/file/load.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

constexpr const char* lock_name = ".lock";

} // namespace

int take_lock(const fs::path& dir, std::string& holder) {
  const fs::path path = dir / lock_name;
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw InvalidArgument("cannot open " + path.string() + ": " + std::strerror(errno));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    // the holder writes its pid just after taking the lock (a new lock file is empty until
    // then): give it a moment, a long one on a loaded machine
    for (int tries = 0; tries < 200 && holder.empty(); ++tries) {
      std::ifstream in(path);
      std::getline(in, holder);
      if (holder.empty()) ::usleep(10'000);
    }
    ::close(fd);
    return -1;
  }
  // the pid over the last holder's, then the rest cut: the first line is never empty or mixed
  // (what follows the newline is left of a longer old pid until the cut), so a process refused
  // meanwhile reads a whole pid
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::pwrite(fd, pid.data(), pid.size(), 0) < 0 ||
      ::ftruncate(fd, static_cast<off_t>(pid.size())) != 0) {
    // the lock holds without the pid; a refused process then names no holder
  }
  return fd;
}

bool in_use(const fs::path& dir, std::string& holder) {
  const fs::path path = dir / lock_name;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false; // no lock file: no run holds it
  const bool held = ::flock(fd, LOCK_SH | LOCK_NB) != 0;
  ::close(fd);
  if (held) {
    std::ifstream in(path);
    std::getline(in, holder);
  }
  return held;
}

namespace {

[[noreturn]] void refuse_in_use(const fs::path& dir, const std::string& holder) {
  throw InvalidArgument("run folder '" + dir.string() + "' is in use by " +
                        (holder.empty() ? std::string("another process") : "process " + holder) +
                        " (talus run or talus resume); wait for it to end, or stop it (a stopped "
                        "run continues with: talus resume " +
                        dir.string() + ")");
}

bool empty_but_lock(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename() != lock_name) return false;
  return true;
}

} // namespace

bool never_checkpointed(const fs::path& dir) {
  // a sweep folder has a lock file too, and must never be taken for a run to clear
  return (fs::exists(dir / "scenario.toml") || fs::exists(dir / lock_name)) &&
         !fs::exists(dir / "sweep.json") && !fs::exists(dir / "checkpoint.bin") &&
         !fs::exists(dir / "checkpoint.prev.bin") && !fs::exists(dir / "run.json");
}

RunFolder RunFolder::create(const std::string& dir, const Scenario& s) {
  return create(dir, to_toml(s));
}

RunFolder RunFolder::create(const std::string& dir, const std::string& scenario_toml) {
  const fs::path d(dir);
  if (fs::exists(d) && !fs::is_directory(d))
    throw InvalidArgument("--out '" + dir + "' is a file, not a folder; choose another with --out");
  const bool existed = fs::exists(d);
  fs::create_directories(d);
  std::string holder;
  const int fd = take_lock(d, holder);
  if (fd < 0) refuse_in_use(d, holder);
  RunFolder folder(d, fd);
  folder.created_ = !existed;
  if (!empty_but_lock(d)) {
    if (!never_checkpointed(d))
      throw InvalidArgument("run folder '" + dir +
                            "' already exists and is not empty; choose another with --out, or "
                            "continue it with: talus resume " +
                            dir);
    // a run stopped before its first checkpoint: nothing in it can be continued
  }
  folder.start_afresh(scenario_toml);
  return folder;
}

void RunFolder::start_afresh(const Scenario& s) {
  start_afresh(to_toml(s));
}

void RunFolder::start_afresh(const std::string& scenario_toml) {
  for (const auto& e : fs::directory_iterator(dir_))
    if (e.path().filename() != lock_name) fs::remove_all(e.path());
  fs::create_directories(dir_ / "snapshots");
  write_file_atomically((dir_ / "scenario.toml").string(), scenario_toml);
}

RunFolder RunFolder::open(const std::string& dir) {
  const fs::path d(dir);
  std::string holder;
  const int fd = take_lock(d, holder);
  if (fd < 0) refuse_in_use(d, holder);
  return RunFolder(d, fd);
}

std::string RunFolder::gone() const {
  struct stat held {};
  struct stat there {};
  if (::fstat(fd_, &held) != 0) return {};
  const fs::path lock = dir_ / lock_name;
  if (held.st_nlink == 0 || ::stat(lock.c_str(), &there) != 0)
    return "the run folder '" + dir_.string() + "' was deleted under the running run";
  if (held.st_dev != there.st_dev || held.st_ino != there.st_ino)
    return "the run folder '" + dir_.string() +
           "' was replaced under the running run (another run's folder is there now)";
  return {};
}

RunFolder::RunFolder(RunFolder&& other) noexcept
    : dir_(std::move(other.dir_)), fd_(other.fd_), created_(other.created_) {
  other.fd_ = -1;
}

RunFolder::~RunFolder() {
  if (fd_ >= 0) ::close(fd_); // releases the lock
}

void RunFolder::discard() {
  std::error_code ignored;
  if (created_) {
    fs::remove_all(dir_, ignored);
    return;
  }
  for (const auto& e : fs::directory_iterator(dir_, ignored))
    if (e.path().filename() != lock_name) fs::remove_all(e.path(), ignored);
}

} // namespace talus::cli
