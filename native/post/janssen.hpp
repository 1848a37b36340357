#pragma once
// Janssen's effect in a silo at rest (Janssen 1895; Sperl 2006, Granular Matter 8: 59, the
// translation): friction on the side walls carries part of the grains' weight, so the stress
// on the walls grows with depth z below the free surface and saturates,
//   sigma_w(z) = sigma_inf (1 - exp(-z / lambda)),
// with sigma_inf = rho_b g W / (2 mu) and lambda = W / (2 K mu) for a silo of width W between two
// walls, rho_b g the bed's weight per area, mu the friction the walls mobilise and K the ratio
// of horizontal to vertical stress (2D: stresses are forces per length of the plane, N/m).
// The wall stress is measured from the wall contacts of snapshots, in bins of depth.
#include <string>
#include <vector>

#include "analysis/frame.hpp"

namespace talus {

struct JanssenOptions {
  double left = 0.0;     ///< m: x of the left wall
  double right = 0.0;    ///< m: x of the right wall
  double gravity = 9.81; ///< m/s^2, its magnitude
  double bin = 0.0;      ///< m: the bins' height (0: eight mean diameters)
};

struct JanssenProfile {
  double surface = 0.0;            ///< m: the bed's free surface, mean over the snapshots
  double base = 0.0;               ///< m: its bottom
  double weight_density = 0.0;     ///< N/m^2: the grains' weight per area of the bed, rho_b g
  double bin = 0.0;                ///< m
  std::vector<double> depth;       ///< m: bin centres below the surface
  std::vector<double> normal;      ///< N/m: the walls' normal stress, mean of the two walls
  std::vector<double> shear;       ///< N/m: the walls' upward friction on the grains, the same way
  std::vector<bool> fitted;        ///< whether the bin is in the fit (not the floor's corner)
  double mobilised_friction = 0.0; ///< sum of shear over sum of normal, both walls, all bins
  bool measured = false;
  std::string why_not;               ///< when not measured
  double saturation = 0.0;           ///< N/m: sigma_inf of the fit
  double saturation_error = 0.0;     ///< N/m: its standard error
  double length = 0.0;               ///< m: lambda of the fit
  double length_error = 0.0;         ///< m
  double rms = 0.0;                  ///< N/m: the bins' scatter about the fit
  double predicted_saturation = 0.0; ///< N/m: rho_b g W / (2 mu_mobilised), Janssen's
  double stress_ratio = 0.0;         ///< K = W / (2 mu_mobilised lambda)
};

/// The wall stress profile of the free grains of `frames` (with their contacts) and its fit.
/// Throws InvalidArgument when the frames hold no wall contact.
JanssenProfile janssen_profile(const std::vector<Frame>& frames, const JanssenOptions& o);

/// sigma_inf (1 - exp(-z / lambda)).
double janssen_stress(double saturation, double length, double depth);

} // namespace talus
