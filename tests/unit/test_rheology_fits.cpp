// The fits of the rheology analysis (post/rheology.hpp, post/line_fit.hpp) on points laid on
// their laws: exact points give the parameters back, noisy ones within their standard errors,
// and too few points are refused with the reason.
#include <gtest/gtest.h>

#include <cmath>

#include "post/rheology.hpp"

namespace talus {
namespace {

// Inertial numbers as a sweep over the plate's speed spreads them, 0.005 to 0.4.
const std::vector<double> inertial{0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4};

// Jop, Forterre & Pouliquen's glass beads (mu_s = tan 20.9 deg, mu_2 = tan 32.76 deg, I_0 =
// 0.279): exact points give them back to 1e-6 (the golden section stops at a bracket of about
// 1e-9 in log I_0; mu_s and mu_2 follow it linearly).
TEST(RheologyFits, MuOfIGivesBackItsParametersFromExactPoints) {
  const double mu_s = 0.382, mu_2 = 0.643, i_0 = 0.279;
  std::vector<double> mu;
  for (const double i : inertial) mu.push_back(mu_of_i(mu_s, mu_2, i_0, i));
  const MuIFit f = fit_mu_of_i(inertial, mu);
  ASSERT_TRUE(f.ok) << f.why_not;
  EXPECT_NEAR(f.mu_s, mu_s, 1e-6);
  EXPECT_NEAR(f.mu_2, mu_2, 1e-6);
  EXPECT_NEAR(f.i_0, i_0, 1e-6 * i_0);
  EXPECT_LT(f.rms, 1e-8);
}

// Noise of 0.005 (a run's typical error on mu) on each point: each parameter within 3 of its
// standard errors, and the errors of the order the noise allows (not 0, not huge).
TEST(RheologyFits, NoisyPointsGiveTheParametersWithinTheirErrors) {
  const double mu_s = 0.26, mu_2 = 0.62, i_0 = 0.3;
  const std::vector<double> noise{0.004, -0.005, 0.003, -0.002, 0.005, -0.004, 0.002};
  std::vector<double> mu;
  for (std::size_t k = 0; k < inertial.size(); ++k)
    mu.push_back(mu_of_i(mu_s, mu_2, i_0, inertial[k]) + noise[k]);
  const MuIFit f = fit_mu_of_i(inertial, mu);
  ASSERT_TRUE(f.ok) << f.why_not;
  EXPECT_NEAR(f.mu_s, mu_s, 3.0 * f.mu_s_error);
  EXPECT_NEAR(f.mu_2, mu_2, 3.0 * f.mu_2_error);
  EXPECT_NEAR(f.i_0, i_0, 3.0 * f.i_0_error);
  EXPECT_GT(f.mu_s_error, 1e-4);
  EXPECT_LT(f.mu_s_error, 0.02);
  EXPECT_NEAR(f.rms, 0.0037, 0.002);
}

// phi = phi_max - a I, da Cruz et al.'s form: exact points to rounding, errors 0 (no scatter).
TEST(RheologyFits, ALineGivesBackItsInterceptAndSlope) {
  std::vector<double> phi;
  for (const double i : inertial) phi.push_back(0.81 - 0.31 * i);
  const LineFit f = fit_line(inertial, phi);
  ASSERT_TRUE(f.ok) << f.why_not;
  EXPECT_NEAR(f.intercept, 0.81, 1e-12);
  EXPECT_NEAR(f.slope, -0.31, 1e-12);
  EXPECT_LT(f.intercept_error, 1e-12);
}

TEST(RheologyFits, TooFewPointsAreRefusedWithTheReason) {
  const MuIFit f = fit_mu_of_i({0.01, 0.1, 0.2}, {0.3, 0.35, 0.4});
  EXPECT_FALSE(f.ok);
  EXPECT_NE(f.why_not.find("4 at least"), std::string::npos) << f.why_not;
  EXPECT_FALSE(fit_mu_of_i({0.0, 0.1, 0.2, 0.3}, {0.3, 0.35, 0.4, 0.45}).ok); // I = 0
  EXPECT_FALSE(fit_line({0.1}, {0.8}).ok);
  EXPECT_FALSE(fit_line({0.1, 0.1, 0.1}, {0.8, 0.79, 0.78}).ok);
}

} // namespace
} // namespace talus
