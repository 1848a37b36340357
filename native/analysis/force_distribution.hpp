#pragma once
// The distribution of normal contact forces (thesis sec. 4.3): P(f/<f>) with the exponential tail
// P ~ exp(-beta f/<f>) above the mean force and a power law below it.
#include <cstddef>
#include <vector>

namespace talus {

struct ForceDistribution {
  double bin_width = 0.0;
  std::vector<double> centre;     ///< bin centres, f/<f>
  std::vector<double> density;    ///< P(f/<f>): sum of density x bin_width is 1
  std::vector<std::size_t> count; ///< contacts per bin
  std::size_t contacts = 0;
  double fraction_below_mean = 0.0; ///< share of contacts carrying less than the mean force
  // exponential tail: ln P = c - beta x, fitted for x >= fit_from over bins with >= 5 contacts,
  // weighted by the counts (the variance of ln P in a bin is about 1/count)
  double beta = 0.0;
  double beta_error = 0.0; ///< one standard error
  double fit_from = 1.0;
  double fit_to = 0.0;
  std::size_t fit_bins = 0;
  // power law below the mean: ln P = c + alpha ln x over 0.1 <= x < 1
  double alpha = 0.0;
};

/// The distribution of forces already divided by their mean (pooled over snapshots).
ForceDistribution force_distribution(const std::vector<double>& scaled_forces,
                                     double bin_width = 0.1);

} // namespace talus
