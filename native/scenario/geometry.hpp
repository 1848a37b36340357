#pragma once
// The thesis' containers and a few more, as named groups of wall segments.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "scenario/scenario.hpp"

namespace talus {

struct ContainerShape {
  /// Wall segments by group: every builder fills "walls" with all of them, plus its own groups
  /// ("floor", "left", "right", "lid", "drum").
  std::map<std::string, std::vector<SegmentSpec>> groups;
  /// Temporary walls during packing (the closed orifice of a hopper or an hourglass).
  std::vector<SegmentSpec> gate;
  Rect fill;   ///< where grains are placed before they settle
  Rect bounds; ///< the container's extent
  /// Drivers the builder implies (the grain press' lid, the drum's rotation).
  std::vector<DriverSection> drivers;
};

/// Whether the container drains through an orifice at y = 0 (hopper, hourglass, a silo with
/// geometry.orifice > 0).
bool has_orifice(const GeometrySection& g);

/// The orifice's ends along y = 0 (has_orifice(g) must hold): x0 and x1, m.
std::pair<double, double> orifice_span(const GeometrySection& g);

/// Builds the container named by g.builder ("none": only g.segments). Throws ScenarioError for
/// missing or inconsistent dimensions, naming the key.
ContainerShape build_container(const GeometrySection& g);

} // namespace talus
