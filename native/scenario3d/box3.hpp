#pragma once
// The sides of a 3D scenario's box: which plates it has, in the order the builder makes them,
// and the names by which drivers take them.
#include <string>
#include <vector>

#include "scenario3d/scenario3.hpp"

namespace talus {

/// A side of the box: its name, a point of it and the normal facing into the box.
struct BoxSide {
  std::string name; ///< "left", "right" (x), "front", "back" (y), "floor", "lid" (z)
  Vec3 point;
  Vec3 normal;
};

/// The box's plates: both sides of every axis that does not wrap, the lid left out when the
/// top is open; the order of the scene's plates.
std::vector<BoxSide> box3_sides(const Box3Section& g);

/// The plates a driver's target names, by index into box3_sides: every plate for "walls", else
/// the one side. Empty when the box has no such side.
std::vector<std::uint32_t> box3_target(const Box3Section& g, const std::string& target);

/// The targets a driver may name in this box, for an error's "allowed:" ("walls" first).
std::string box3_targets(const Box3Section& g);

} // namespace talus
