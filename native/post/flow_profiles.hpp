#pragma once
// Flow seen in snapshots (thesis sec. 4.1, figs. 4.6-4.10): time-averaged velocity across a
// horizontal band and a false-colour map of the mean speed (the discharge: post/discharge.hpp).
#include <cstddef>
#include <vector>

#include "analysis/frame.hpp"
#include "scenario/scenario.hpp"

namespace talus {

/// Mean velocity of the free grains whose centres lie in a band y0 <= y < y1, in bins across x,
/// pooled over frames (each grain in each frame is one sample).
struct BandProfile {
  double y0 = 0.0, y1 = 0.0;
  std::vector<double> x;          ///< bin centres, m
  std::vector<double> vx, vy;     ///< mean velocity components, m/s
  std::vector<double> speed;      ///< mean |v|, m/s
  std::vector<std::size_t> count; ///< samples per bin
};

BandProfile band_profile(const std::vector<Frame>& frames, double y0, double y1, double x0,
                         double x1, std::size_t bins);

/// Mean speed of the free grains on a grid of square cells over `region`, pooled over frames.
struct SpeedMap {
  Rect region;
  double cell = 0.0;              ///< m
  std::size_t nx = 0, ny = 0;     ///< cells across and up
  std::vector<double> mean_speed; ///< row-major from the bottom left; m/s, 0 where empty
  std::vector<std::size_t> count; ///< samples per cell
};

SpeedMap speed_map(const std::vector<Frame>& frames, const Rect& region, double cell);

/// Least-squares slope of y against x (0 for fewer than two points).
double slope(const std::vector<double>& x, const std::vector<double>& y);

} // namespace talus
