// The restitution error `talus run` prints for its timestep (docs/accuracy.md): the linear law's
// onset estimate pi zeta dt / t_c, and the Hertz law's measured table, interpolated.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scenario/file/load.hpp"
#include "scenario/timestep_accuracy.hpp"
#include "talus/closed_forms.hpp"

namespace talus {
namespace {

Scenario two_disks(const std::string& law, double restitution, double factor) {
  return load_scenario(R"(name = "two"
[simulation]
duration = 0.01
gravity = [0.0, 0.0]
normal_law = ")" + law + R"("
timestep_factor = )" + std::to_string(factor) +
                           R"(
[[materials]]
name = "grain"
normal_stiffness = 1.0e4
restitution = )" + std::to_string(restitution) +
                           R"(
[particles]
shape = "disk"
[[particles.list]]
position = [0.0, 0.0]
radius = 0.001
[[particles.list]]
position = [0.003, 0.0]
radius = 0.002
)",
                       "two.toml");
}

TEST(TimestepAccuracy, LinearOnsetIsPiZetaDtOverTc) {
  for (const double factor : {20.0, 50.0, 400.0}) {
    const BuiltScenario b = build_scenario(two_disks("linear", 0.5, factor));
    const RestitutionError e = expected_restitution_error(b);
    // the mixed pair's zeta is that of the restitution (the dashpot is 2 zeta sqrt(k m_eff))
    const double zeta = linear_damping_ratio(0.5);
    EXPECT_NEAR(e.error, std::numbers::pi * zeta / factor, 1e-12 * e.error) << factor;
    EXPECT_NE(e.basis.find("onset"), std::string::npos);
  }
  // an undamped spring has no onset jump: no estimate
  const RestitutionError none =
      expected_restitution_error(build_scenario(two_disks("linear", 1.0, 50.0)));
  EXPECT_TRUE(none.basis.empty()) << none.basis << " " << none.error;
}

TEST(TimestepAccuracy, HertzFollowsItsMeasuredTable) {
  EXPECT_DOUBLE_EQ(hertz_restitution_error(50.0, 0.99), 5.89e-5); // measured points
  EXPECT_DOUBLE_EQ(hertz_restitution_error(50.0, 0.5), 2.22e-3);
  // between factors: log-log, so the geometric mean of t_c/100 and t_c/200's at their own mean
  EXPECT_NEAR(hertz_restitution_error(std::sqrt(100.0 * 200.0), 0.99), std::sqrt(1.32e-5 * 4.87e-6),
              1e-18);
  // between restitutions: the log of the error linear in e
  EXPECT_NEAR(hertz_restitution_error(50.0, 0.6), std::sqrt(2.22e-3 * 1.18e-3), 1e-15);
  // beyond the table: second order; before it, the coarsest measured; e outside 0.1 to 0.99: the
  // nearest row
  EXPECT_NEAR(hertz_restitution_error(2000.0, 0.99), 2.54e-7 / 4.0, 1e-20);
  EXPECT_DOUBLE_EQ(hertz_restitution_error(2.0, 0.99), 1.78e-2);
  EXPECT_DOUBLE_EQ(hertz_restitution_error(50.0, 1.0), 5.89e-5);
  EXPECT_DOUBLE_EQ(hertz_restitution_error(50.0, 0.05), 6.77e-3);
  // a scene's estimate is at the lowest restitution of its pairs: here the derived damping gives
  // e = 0.9 at the impact speed (hertz_restitution is good to 1e-8 in e)
  const BuiltScenario b = build_scenario(two_disks("hertz", 0.9, 50.0));
  const RestitutionError e = expected_restitution_error(b);
  EXPECT_NEAR(e.error, 3.55e-4, 1e-8);
  EXPECT_NE(e.basis.find("e = 0.9"), std::string::npos) << e.basis;
}

} // namespace
} // namespace talus
