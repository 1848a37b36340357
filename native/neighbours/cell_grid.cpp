#include "neighbours/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "talus/error.hpp"

namespace talus {

namespace {
// Number of cells of width >= range along one direction of length `length`.
int cells_along(double length, double range, bool periodic, const char* axis) {
  if (periodic) {
    const double n = std::floor(length / range);
    require(n >= min_periodic_cells, std::string("periodic box too small along ") + axis + ": " +
                                         std::to_string(length) + " m holds fewer than " +
                                         std::to_string(min_periodic_cells) +
                                         " interaction ranges of " + std::to_string(range) +
                                         " m (2 x largest radius + skin)");
    return static_cast<int>(std::min(n, 1.0e6));
  }
  return static_cast<int>(std::clamp(std::floor(length / range) + 1.0, 1.0, 1.0e6));
}
} // namespace

int CellGrid::cell_x(double x) const {
  const int c = static_cast<int>(std::floor((x - origin.x) / cell_size.x));
  return std::clamp(c, 0, nx - 1);
}

int CellGrid::cell_y(double y) const {
  const int c = static_cast<int>(std::floor((y - origin.y) / cell_size.y));
  return std::clamp(c, 0, ny - 1);
}

void CellGrid::build(const std::vector<Vec2>& positions, const Domain& domain, double range,
                     int threads) {
  periodic_x = domain.periodic_x;
  periodic_y = domain.periodic_y;
  const auto n = static_cast<std::ptrdiff_t>(positions.size());
  double lx = std::numeric_limits<double>::max(), ly = lx;
  double hx = std::numeric_limits<double>::lowest(), hy = hx;
#pragma omp parallel for num_threads(threads) reduction(min : lx, ly) reduction(max : hx, hy)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    lx = std::min(lx, positions[i].x), ly = std::min(ly, positions[i].y);
    hx = std::max(hx, positions[i].x), hy = std::max(hy, positions[i].y);
  }
  Vec2 lo{lx, ly}, hi{hx, hy};
  if (positions.empty()) lo = hi = {};
  if (periodic_x) lo.x = domain.lo.x, hi.x = domain.hi.x;
  if (periodic_y) lo.y = domain.lo.y, hi.y = domain.hi.y;
  double rx = range, ry = range;
  nx = cells_along(hi.x - lo.x, rx, periodic_x, "x");
  ny = cells_along(hi.y - lo.y, ry, periodic_y, "y");
  // Sparse outliers must not blow up memory: keep the cell count within a few per particle.
  const double max_cells = 4.0 * static_cast<double>(positions.size()) + 16.0;
  while (static_cast<double>(nx) * ny > max_cells) {
    if (!periodic_x && nx > 1) rx *= 1.5, nx = cells_along(hi.x - lo.x, rx, false, "x");
    if (!periodic_y && ny > 1) ry *= 1.5, ny = cells_along(hi.y - lo.y, ry, false, "y");
    if ((periodic_x || nx == 1) && (periodic_y || ny == 1)) break;
  }
  origin = lo;
  cell_size = {periodic_x ? (hi.x - lo.x) / nx : rx, periodic_y ? (hi.y - lo.y) / ny : ry};

  const std::size_t n_cells = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  cell_start.assign(n_cells + 1, 0);
  cell_of.resize(positions.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    cell_of[i] = static_cast<std::uint32_t>(cell_y(positions[i].y) * nx + cell_x(positions[i].x));
  for (const std::uint32_t c : cell_of) ++cell_start[c + 1];
  for (std::size_t c = 0; c < n_cells; ++c) cell_start[c + 1] += cell_start[c];
  items.resize(positions.size());
  std::vector<std::uint32_t> fill(cell_start.begin(), cell_start.end() - 1);
  for (std::size_t i = 0; i < positions.size(); ++i)
    items[fill[cell_of[i]]++] = static_cast<std::uint32_t>(i);
}

} // namespace talus
