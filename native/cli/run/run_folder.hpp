#pragma once
// A run folder held by one process: `talus run` and `talus resume` take an advisory lock on
// DIR/.lock (flock), which the system releases when the process ends however it ends, so a
// second process on the same folder is refused with the holder's pid, and a killed run's folder
// is free again at once.
#include <filesystem>
#include <string>

#include "scenario/scenario.hpp"

namespace talus::cli {

class RunFolder {
public:
  /// A folder for a new run: `dir` must not exist, be empty, or hold a run that was stopped
  /// before its first checkpoint (killed while settling, say), which is cleared. Takes the lock,
  /// makes snapshots/ and writes the scenario as scenario.toml. Throws InvalidArgument (naming
  /// the holder's pid, or saying how to continue the run already there) otherwise.
  static RunFolder create(const std::string& dir, const Scenario& s);
  /// The same with the resolved scenario's text (a 3D scenario's).
  static RunFolder create(const std::string& dir, const std::string& scenario_toml);
  /// A run folder to resume: takes the lock. Throws InvalidArgument if another process holds it.
  static RunFolder open(const std::string& dir);

  RunFolder(RunFolder&& other) noexcept;
  RunFolder& operator=(RunFolder&&) = delete;
  RunFolder(const RunFolder&) = delete;
  ~RunFolder();

  const std::filesystem::path& path() const { return dir_; }
  /// Empties the folder but for its lock, makes snapshots/ and writes the scenario as
  /// scenario.toml: a new run's start (a run stopped before its first checkpoint starts again).
  void start_afresh(const Scenario& s);
  void start_afresh(const std::string& scenario_toml);
  /// Why the folder at path() is no longer the one this object locked (deleted, moved, or
  /// replaced by another run's folder), or empty while it is: the lock file there must be the
  /// one whose lock is held.
  std::string gone() const;
  /// Removes what create() wrote (the scenario could not be built: nothing is left behind).
  void discard();

private:
  RunFolder(std::filesystem::path dir, int fd) : dir_(std::move(dir)), fd_(fd) {}
  std::filesystem::path dir_;
  int fd_ = -1;
  bool created_ = false; ///< create() made the folder (discard removes it)
};

/// The advisory lock on dir/.lock (as a run folder takes it; a sweep folder takes the same): its
/// file descriptor, held until closed or the process ends, or -1 with the holder's pid in
/// `holder` (empty if unknown).
int take_lock(const std::filesystem::path& dir, std::string& holder);

/// Whether a process holds dir's lock (its pid in `holder`, empty if unknown); looks without
/// taking it or writing anything.
bool in_use(const std::filesystem::path& dir, std::string& holder);

/// Whether dir holds a run that never wrote a checkpoint (and has not ended): a folder talus made
/// (it has the lock file or scenario.toml; not a sweep folder) with no checkpoint and no run.json.
/// A run killed at its very start may have left the lock file and little else.
bool never_checkpointed(const std::filesystem::path& dir);

} // namespace talus::cli
