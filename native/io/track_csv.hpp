#pragma once
// Reads back a run folder's track.csv (written by `talus run` for the tracked particles).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/vec2.hpp"

namespace talus {

struct TrackPoint {
  double time;    ///< s
  Vec2 position;  ///< m, inside a periodic box
  Vec2 velocity;  ///< m/s
  Vec2 unwrapped; ///< m: the position with the periodic boundaries crossed undone
};

/// The tracks by particle id, each in time order. A file without the unwrapped columns (xu, yu:
/// written before them) reads its positions as unwrapped. Throws std::runtime_error naming the file
/// and the line that is malformed; a missing file is an error too.
std::map<std::uint32_t, std::vector<TrackPoint>> read_tracks(const std::string& path);

} // namespace talus
