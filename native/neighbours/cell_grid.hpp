#pragma once
// A uniform grid of square-ish cells over the particles, with a counting sort into cells.
#include <cstdint>
#include <vector>

#include "core/domain.hpp"
#include "core/vec2.hpp"

namespace talus {

/// A periodic direction must hold this many cells at least: the 3 x 3 stencil around a cell
/// would otherwise meet the same cell twice.
inline constexpr int min_periodic_cells = 3;

struct CellGrid {
  Vec2 origin;
  Vec2 cell_size;
  int nx = 1;
  int ny = 1;
  bool periodic_x = false;
  bool periodic_y = false;
  std::vector<std::uint32_t> cell_start; ///< nx*ny + 1 offsets into `items`
  std::vector<std::uint32_t> items;      ///< particle indices grouped by cell, ascending in a cell
  std::vector<std::uint32_t> cell_of;    ///< cell of each particle

  /// Lays out cells at least `range` wide over the positions (or the domain along periodic
  /// directions) and sorts the particles into them.
  /// `threads` share the per-particle work (the result does not depend on their number).
  void build(const std::vector<Vec2>& positions, const Domain& domain, double range,
             int threads = 1);
  int cell_x(double x) const;
  int cell_y(double y) const;
};

} // namespace talus
