#pragma once
// The angle of repose of a heap at rest, from a snapshot: its free surface (the highest grain
// top in bins across x) and a straight line fitted to each flank's middle part, as a heap
// poured or slumped in the laboratory is measured from its profile.
#include <string>
#include <vector>

#include "analysis/frame.hpp"

namespace talus {

/// One flank of the heap: a straight line fitted to its surface where the surface lies between
/// `surface_band` of the heap's height (the toe and the rounded top left out).
struct ReposeFlank {
  bool measured = false;
  std::string why_not; ///< when not measured
  double slope = 0.0;  ///< dh/dx of the fit
  double intercept = 0.0;
  double angle_deg = 0.0; ///< atan(|slope|)
  double rms = 0.0;       ///< m: the surface's scatter about the line
  std::size_t points = 0;
};

struct ReposeProfile {
  double bin_width = 0.0;      ///< m: two mean grain diameters
  double base = 0.0;           ///< m: the lowest grain's lowest point
  double height = 0.0;         ///< m: the highest grain top above the base
  double peak_x = 0.0;         ///< m: the bin of the highest grain top
  std::vector<double> x;       ///< m: the centres of the bins with grains
  std::vector<double> surface; ///< m: the highest grain top in each
  /// -1: a point of the left flank's fit, +1: of the right flank's, 0: neither
  std::vector<int> flank;
  ReposeFlank left, right;
  /// The mean angle of the flanks measured (NaN if neither was).
  double angle_deg = 0.0;
};

/// The part of the heap's height, from its base, whose surface the flanks' lines are fitted to.
inline constexpr double surface_band_low = 0.2, surface_band_high = 0.8;

/// The heap of the free grains of frame f. A flank needs three bins in the band to be measured.
ReposeProfile repose_profile(const Frame& f);

} // namespace talus
