#pragma once
// Checkpoints of a 3D run: the whole Simulation3 state and its settings, and the run's own
// bookkeeping, in one binary file with its own magic word, a format version and a checksum
// (written atomically with write_file_atomically, as the 2D checkpoints).
#include <cstdint>
#include <string>

#include "engine3d/simulation3.hpp"
#include "io/checkpoint.hpp"

namespace talus {

struct Checkpoint3 {
  SimulationState3 state;
  Settings3 settings;
  std::string run_data; ///< opaque to the engine: the command line's own bookkeeping
};

/// The format written (read: this one only, for now).
/// 2: rolling springs and Gear; 3: the renumbering interval; 4: the servos
inline constexpr std::uint32_t checkpoint3_version = 5;

/// The bytes of a 3D checkpoint file.
std::string encode_checkpoint3(const Checkpoint3& c);
/// Parses 3D checkpoint bytes; throws CheckpointError naming `source` and what is wrong (not a
/// 3D checkpoint, another version, truncated, a checksum or a field that does not add up).
Checkpoint3 decode_checkpoint3(const std::string& bytes, const std::string& source);

} // namespace talus
