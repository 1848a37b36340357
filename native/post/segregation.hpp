#pragma once
// Size segregation seen in snapshots (thesis sec. 4.2, the Brazil-nut effect): where the largest
// grains are, a segregation index, and the convection of the small grains.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "analysis/frame.hpp"

namespace talus {

struct SegregationSeries {
  double large_radius = 0.0; ///< m: grains at least this large count as large
  std::size_t large_count = 0;
  std::vector<std::uint32_t> largest; ///< ids of the largest grains (at most 6), largest first
  std::vector<double> time;           ///< s, one per frame
  std::vector<double> bed_height;     ///< m: top of the bed above its bottom
  /// (mean height of large - mean height of small) / bed height, heights of centres above the
  /// bed's bottom: +1/2 when the large grains float on top, about 0 when mixed
  std::vector<double> index;
  std::vector<std::vector<double>> largest_height; ///< [frame][k]: centre above the bed's bottom
  std::vector<double> largest_depth_fraction;      ///< of the largest: (top - (y + R)) / bed height
};

/// `large_radius` <= 0 picks the split itself: grains with R >= 1.5 x the median radius if
/// there are any, else the largest tenth. Only free grains count; the bed's bottom is its
/// lowest grain's lowest point and its top the 98th percentile of y + R.
SegregationSeries segregation(const std::vector<Frame>& frames, double large_radius = 0.0);

/// Mean vertical drift of the small grains between consecutive frames, in bins across x:
/// down by the walls and up at the centre for convection rolls (thesis fig. 4.11).
struct ConvectionProfile {
  std::vector<double> x;          ///< bin centres, m
  std::vector<double> drift;      ///< mean dy/dt of small grains, m/s
  std::vector<std::size_t> count; ///< samples
};

ConvectionProfile convection(const std::vector<Frame>& frames, double large_radius,
                             std::size_t bins);

} // namespace talus
