// The force-distribution fit recovers known distributions.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/force_distribution.hpp"
#include "core/random.hpp"

namespace talus {
namespace {

// f/<f> drawn from exp(-x) (beta = 1 exactly): the fit must find it within its own error bars.
TEST(ForceDistribution, RecoversAnExponentialTail) {
  RandomStream rng(5, 0);
  std::vector<double> f(200000);
  for (double& v : f) v = -std::log(1.0 - rng.uniform());
  const ForceDistribution d = force_distribution(f);
  EXPECT_NEAR(d.beta, 1.0, 4.0 * d.beta_error);
  EXPECT_LT(d.beta_error, 0.02);
  EXPECT_NEAR(d.fraction_below_mean, 1.0 - std::exp(-1.0), 0.01);
  double total = 0.0;
  for (const double p : d.density) total += p * d.bin_width;
  EXPECT_NEAR(total, 1.0, 1e-12);
}

// A steeper tail, P ~ exp(-1.8 x) above 1 (the 2D literature's range is about 1.4 to 1.9).
TEST(ForceDistribution, RecoversASteeperTail) {
  RandomStream rng(6, 0);
  std::vector<double> f(200000);
  for (double& v : f)
    v = rng.uniform() < 0.6 ? rng.uniform() : 1.0 - std::log(1.0 - rng.uniform()) / 1.8;
  const ForceDistribution d = force_distribution(f);
  EXPECT_NEAR(d.beta, 1.8, 4.0 * d.beta_error);
}

} // namespace
} // namespace talus
