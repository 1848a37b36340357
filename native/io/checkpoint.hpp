#pragma once
// Checkpoints: the whole simulation state, and the run's own bookkeeping, in one binary file
// with a magic word, a format version and a checksum, written atomically.
#include <stdexcept>
#include <string>
#include <string_view>

#include "simulation/simulation.hpp"

namespace talus {

/// A file could not be written (a full disk, a file size limit, no permission). `error` is the
/// system's errno for it where one is known, 0 otherwise.
class WriteError : public std::runtime_error {
public:
  explicit WriteError(const std::string& what, int error = 0)
      : std::runtime_error(what), error_(error) {}
  [[nodiscard]] int error() const { return error_; }

private:
  int error_;
};

/// A checkpoint that cannot be used: missing, truncated, corrupted or of another version.
class CheckpointError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct Checkpoint {
  SimulationState state;
  SimulationConfig config;
  std::string run_data; ///< opaque to the engine: the command line's own bookkeeping
};

/// The format written. 7: the lever arm in the config; 8: FNV-1a's own offset basis in the
/// checksum (7 had one a digit short); 9: a driver's start time; 10: the particles' periodic
/// image counts; 11: rolling resistance (the materials' keys and the rolling springs); 12: the
/// linear law's damping convention; 13: the timestep's clock (a timestep changed during a run);
/// 14: a servo's slide speed; 15: the deforming cell (a cell driver, the box at the list's
/// build); 16: Lees-Edwards images (the domain's offset and velocity, the offset at the list's
/// build, a cell's shear). Versions 7 to 16 are read.
inline constexpr std::uint32_t checkpoint_version = 16;

/// The bytes of a checkpoint file.
std::string encode_checkpoint(const Checkpoint& c);
/// FNV-1a's 64-bit hash of `bytes`, the checksum a checkpoint is sealed with.
std::uint64_t fnv1a_hash(std::string_view bytes);
/// A checkpoint's bytes around its payload (every field, in order): the magic word, the format
/// version, the payload's size, the payload and its checksum. encode_checkpoint seals what it
/// writes; the checkpoint fuzzer seals what it makes up, so that its inputs get past the
/// checksum to the fields.
std::string seal_checkpoint(const std::string& payload);
/// Parses checkpoint bytes; throws CheckpointError naming `source` and what is wrong.
Checkpoint decode_checkpoint(const std::string& bytes, const std::string& source);

/// Writes `bytes` to path atomically: a temporary file, flushed and fsync'ed, then renamed over
/// path. Throws WriteError naming the file (full disk, no permission) and leaves no
/// partial file behind.
void write_file_atomically(const std::string& path, const std::string& bytes);
/// Reads a whole file; throws std::runtime_error naming it.
std::string read_file(const std::string& path);

} // namespace talus
