#include "frost/resting_pairs.hpp"

#include <algorithm>
#include <limits>

namespace talus {

std::vector<std::pair<std::uint32_t, std::uint32_t>>
resting_pairs(const Particles& p, const std::vector<std::uint32_t>& grains, double cell,
              double x_min, double x_max) {
  double y_lo = std::numeric_limits<double>::infinity(), y_hi = -y_lo;
  for (const std::uint32_t i : grains) {
    y_lo = std::min(y_lo, p.position[i].y - p.radius[i]);
    y_hi = std::max(y_hi, p.position[i].y + p.radius[i]);
  }
  const double x_lo = x_min - cell;
  const auto nx = static_cast<std::size_t>((x_max + cell - x_lo) / cell) + 1;
  const auto ny = static_cast<std::size_t>((y_hi - y_lo) / cell) + 1;
  const auto span = [&](std::size_t i, std::size_t& cx0, std::size_t& cx1, std::size_t& cy0,
                        std::size_t& cy1) {
    const double r = p.radius[i];
    const auto clamp_x = [&](double x) {
      return std::min(nx - 1, static_cast<std::size_t>(std::max(0.0, (x - x_lo) / cell)));
    };
    const auto clamp_y = [&](double y) {
      return std::min(ny - 1, static_cast<std::size_t>(std::max(0.0, (y - y_lo) / cell)));
    };
    cx0 = clamp_x(p.position[i].x - r), cx1 = clamp_x(p.position[i].x + r);
    cy0 = clamp_y(p.position[i].y - r), cy1 = clamp_y(p.position[i].y + r);
  };
  std::vector<std::uint32_t> start(nx * ny + 1, 0), items;
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (const std::uint32_t i : grains) {
      std::size_t cx0, cx1, cy0, cy1;
      span(i, cx0, cx1, cy0, cy1);
      for (std::size_t cy = cy0; cy <= cy1; ++cy)
        for (std::size_t cx = cx0; cx <= cx1; ++cx)
          if (pass == 0)
            ++start[cy * nx + cx + 1];
          else
            items[fill[cy * nx + cx]++] = i;
    }
    if (pass == 0) {
      for (std::size_t c = 0; c < nx * ny; ++c) start[c + 1] += start[c];
      items.resize(start.back());
    }
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> rests; // (lower, upper)
  std::vector<std::uint32_t> seen(p.size(), static_cast<std::uint32_t>(-1));
  for (const std::uint32_t i : grains) {
    std::size_t cx0, cx1, cy0, cy1;
    span(i, cx0, cx1, cy0, cy1);
    for (std::size_t cy = cy0; cy <= cy1; ++cy)
      for (std::size_t cx = cx0; cx <= cx1; ++cx)
        for (std::uint32_t k = start[cy * nx + cx]; k < start[cy * nx + cx + 1]; ++k) {
          const std::uint32_t j = items[k];
          if (j <= i || seen[j] == i) continue;
          seen[j] = i;
          const double gap = 0.1 * std::min(p.radius[i], p.radius[j]);
          const double reach = p.radius[i] + p.radius[j] + gap;
          if (norm2(p.position[i] - p.position[j]) >= reach * reach) continue;
          const bool i_lower = p.position[i].y < p.position[j].y;
          rests.emplace_back(i_lower ? i : j, i_lower ? j : i);
        }
  }
  return rests;
}

} // namespace talus
