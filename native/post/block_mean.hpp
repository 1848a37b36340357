#pragma once
// The mean of one value over consecutive blocks of a run's snapshots, and its standard error:
// blocks of a steady state a few correlation times long are nearly independent samples of it.
#include <cmath>
#include <utility>
#include <vector>

namespace talus {

/// The mean of `field` over `blocks` and its standard error (blocks - 1 degrees of freedom).
template <class Block>
std::pair<double, double> block_mean_error(const std::vector<Block>& blocks, double Block::*field) {
  const auto n = static_cast<double>(blocks.size());
  double mean = 0.0, var = 0.0;
  for (const Block& b : blocks) mean += b.*field / n;
  for (const Block& b : blocks) var += (b.*field - mean) * (b.*field - mean) / (n - 1.0);
  return {mean, std::sqrt(var / n)};
}

} // namespace talus
