// The Beverloo fit (post/beverloo.hpp) on rates made from known parameters.
#include <gtest/gtest.h>

#include <cmath>

#include "post/beverloo.hpp"

namespace talus {
namespace {

constexpr double grain_d = 0.01; // m

std::vector<double> rates(const std::vector<double>& D, double A, double k, double n,
                          double wobble = 0.0) {
  std::vector<double> W;
  for (std::size_t i = 0; i < D.size(); ++i)
    W.push_back(A * std::pow(D[i] / grain_d - k, n) * (1.0 + wobble * ((i % 2) ? 1.0 : -1.0)));
  return W;
}

const std::vector<double> widths{0.04, 0.04, 0.05, 0.06, 0.06, 0.08, 0.1, 0.12, 0.12};

TEST(Beverloo, ExactRatesGiveTheirParametersBack) {
  const auto W = rates(widths, 20.0, 1.4, 1.5);
  const BeverlooFit f = fit_beverloo(widths, W, grain_d);
  ASSERT_TRUE(f.ok) << f.why_not;
  // exact data: the least squares minimum is the truth, up to the solver's convergence
  EXPECT_NEAR(f.A, 20.0, 1e-4);
  EXPECT_NEAR(f.k, 1.4, 1e-5);
  EXPECT_NEAR(f.n, 1.5, 1e-5);
  EXPECT_NEAR(f.C, 20.0 * std::pow(grain_d, -1.5), 1e-4 * std::pow(grain_d, -1.5));
  EXPECT_LT(f.rms, 1e-6);
  EXPECT_NEAR(beverloo_rate(f, 0.08, grain_d), 20.0 * std::pow(8.0 - 1.4, 1.5), 1e-3);
}

TEST(Beverloo, ScatterIsCoveredByTheStatedErrors) {
  // +-3% alternating scatter on n = 1.7: the fitted values lie within three standard errors
  const auto W = rates(widths, 12.0, 0.9, 1.7, 0.03);
  const BeverlooFit f = fit_beverloo(widths, W, grain_d);
  ASSERT_TRUE(f.ok) << f.why_not;
  EXPECT_GT(f.n_error, 0.0);
  EXPECT_NEAR(f.n, 1.7, 3.0 * f.n_error);
  EXPECT_NEAR(f.k, 0.9, 3.0 * f.k_error);
  EXPECT_NEAR(f.A, 12.0, 3.0 * f.A_error);
}

TEST(Beverloo, FixedExponentFitsAAndKOnly) {
  const auto W = rates(widths, 20.0, 1.4, 1.5);
  const BeverlooFit f = fit_beverloo(widths, W, grain_d, 1.5);
  ASSERT_TRUE(f.ok) << f.why_not;
  EXPECT_TRUE(f.n_fixed);
  EXPECT_DOUBLE_EQ(f.n, 1.5);
  EXPECT_EQ(f.n_error, 0.0);
  EXPECT_NEAR(f.k, 1.4, 1e-5);
  EXPECT_NEAR(f.A, 20.0, 1e-4);
}

TEST(Beverloo, TooFewWidthsAreRefusedWithTheReason) {
  const std::vector<double> D{0.04, 0.04, 0.06, 0.06};
  const BeverlooFit f = fit_beverloo(D, rates(D, 20.0, 1.4, 1.5), grain_d);
  EXPECT_FALSE(f.ok);
  EXPECT_NE(f.why_not.find("at least 3 orifice widths"), std::string::npos) << f.why_not;
  EXPECT_TRUE(fit_beverloo(D, rates(D, 20.0, 1.4, 1.5), grain_d, 1.5).ok); // two parameters: enough
}

} // namespace
} // namespace talus
