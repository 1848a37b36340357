#pragma once
// Pictures of one moment of a run: grains coloured by a field with a colour bar, walls as lines.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/frame.hpp"
#include "scenario/scenario.hpp"

namespace talus {

enum class SnapshotColour { speed, size, force, kind, material };

/// Parses "speed", "size", "force", "kind" or "material"; throws InvalidArgument otherwise.
SnapshotColour parse_colour(std::string_view name);

/// A tracked particle's path, drawn over the picture (thesis figs. 4.3-4.5, 4.11, 5.13).
struct TrackLine {
  std::uint32_t id;
  std::vector<Vec2> points; ///< m, in time order
};

struct PictureOptions {
  int width_px = 1200;
  SnapshotColour colour = SnapshotColour::speed;
  std::optional<Rect> bounds; ///< the region drawn; default: everything in the frame
  std::optional<std::pair<double, double>> range; ///< colour scale; default: the frame's own
  bool chains = false;                            ///< force chains over faded grains
  std::optional<double> chain_scale; ///< force drawn widest, N; default: the frame's largest
  std::vector<TrackLine> tracks;     ///< trajectories over faded grains, one colour each
};

/// Draws a frame into a PNG (Cairo). Continuous fields get a colour bar with their range and
/// unit; kind and material get one colour each. Throws std::runtime_error naming the file.
void write_frame_png(const Frame& frame, const std::string& path, const PictureOptions& o = {});

/// The extent of a frame's grains and walls.
Rect frame_bounds(const Frame& frame);

/// The current state of a simulation.
inline void write_snapshot_png(const Simulation& sim, const std::string& path, int width_px = 1200,
                               SnapshotColour colour = SnapshotColour::speed) {
  write_frame_png(frame_of(sim), path, {width_px, colour, {}, {}, false, {}, {}});
}

} // namespace talus
