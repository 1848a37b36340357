#include "post/flow_profiles.hpp"

#include <algorithm>
#include <cmath>

#include "talus/error.hpp"

namespace talus {

BandProfile band_profile(const std::vector<Frame>& frames, double y0, double y1, double x0,
                         double x1, std::size_t bins) {
  if (!(y1 > y0) || !(x1 > x0) || bins == 0)
    throw InvalidArgument("a band profile needs y1 > y0, x1 > x0 and at least one bin");
  BandProfile p;
  p.y0 = y0, p.y1 = y1;
  const double w = (x1 - x0) / static_cast<double>(bins);
  std::vector<double> sx(bins), sy(bins), ss(bins);
  p.count.assign(bins, 0);
  for (const Frame& f : frames)
    for (std::size_t i = 0; i < f.position.size(); ++i) {
      const Vec2 r = f.position[i];
      if (f.kind[i] != 0 || r.y < y0 || r.y >= y1 || r.x < x0 || r.x >= x1) continue;
      const auto b = std::min(bins - 1, static_cast<std::size_t>((r.x - x0) / w));
      sx[b] += f.velocity[i].x, sy[b] += f.velocity[i].y, ss[b] += norm(f.velocity[i]);
      ++p.count[b];
    }
  for (std::size_t b = 0; b < bins; ++b) {
    const double n = std::max<double>(1.0, static_cast<double>(p.count[b]));
    p.x.push_back(x0 + (static_cast<double>(b) + 0.5) * w);
    p.vx.push_back(sx[b] / n), p.vy.push_back(sy[b] / n), p.speed.push_back(ss[b] / n);
  }
  return p;
}

SpeedMap speed_map(const std::vector<Frame>& frames, const Rect& region, double cell) {
  const Vec2 size = region.hi - region.lo;
  if (!(cell > 0.0) || !(size.x > 0.0) || !(size.y > 0.0))
    throw InvalidArgument("a speed map needs a cell > 0 and a region of positive size");
  SpeedMap m;
  m.region = region, m.cell = cell;
  m.nx = static_cast<std::size_t>(std::ceil(size.x / cell));
  m.ny = static_cast<std::size_t>(std::ceil(size.y / cell));
  m.mean_speed.assign(m.nx * m.ny, 0.0);
  m.count.assign(m.nx * m.ny, 0);
  for (const Frame& f : frames)
    for (std::size_t i = 0; i < f.position.size(); ++i) {
      const Vec2 r = f.position[i] - region.lo;
      if (f.kind[i] != 0 || r.x < 0.0 || r.y < 0.0 || r.x >= size.x || r.y >= size.y) continue;
      const std::size_t c =
          static_cast<std::size_t>(r.y / cell) * m.nx + static_cast<std::size_t>(r.x / cell);
      m.mean_speed[c] += norm(f.velocity[i]);
      ++m.count[c];
    }
  for (std::size_t c = 0; c < m.count.size(); ++c)
    if (m.count[c] > 0) m.mean_speed[c] /= static_cast<double>(m.count[c]);
  return m;
}

double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = std::min(x.size(), y.size());
  if (n < 2) return 0.0;
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < n; ++k) mx += x[k], my += y[k];
  mx /= static_cast<double>(n), my /= static_cast<double>(n);
  double sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < n; ++k)
    sxy += (x[k] - mx) * (y[k] - my), sxx += (x[k] - mx) * (x[k] - mx);
  return sxx > 0.0 ? sxy / sxx : 0.0;
}

} // namespace talus
