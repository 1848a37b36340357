#pragma once
// A picture of one moment of a run: grains coloured by speed or size, walls drawn as lines.
#include <string>

#include "simulation/simulation.hpp"

namespace talus {

enum class SnapshotColour { size, speed };

/// Draws the current state into a PNG `width_px` wide (Cairo), with a colour bar. Throws
/// std::runtime_error naming the file if it cannot be written.
void write_snapshot_png(const Simulation& sim, const std::string& path, int width_px = 1200,
                        SnapshotColour colour = SnapshotColour::speed);

} // namespace talus
