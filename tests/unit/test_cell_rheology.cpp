// The rheology of a sheared cell (post/rheology.hpp, cell_rheology_point) from made-up thermo rows
// and snapshots whose numbers are known, of disks and of spheres: mu, phi and I come back exactly,
// the grains' profile gives its slope back, and too little data is refused with the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "post/rheology.hpp"

namespace talus {
namespace {

// Rows with sigma_xy = -30 N/m and sigma_yy = 100 N/m (mu = 0.3), phi = 0.8, at 2 1/s.
std::vector<CellShearRow> rows(std::size_t n) {
  std::vector<CellShearRow> out;
  for (std::size_t k = 0; k < n; ++k)
    out.push_back({.time = 0.01 * static_cast<double>(k),
                   .shear_stress = -30.0,
                   .normal_stress = 100.0,
                   .packing = 0.8,
                   .shear_rate = 2.0});
  return out;
}

// Grains of radius 5 mm and 2650 kg/m^2 on a column, moving at v_x = slope y (+ 1 m/s).
std::vector<Frame> frames(std::size_t n, double slope) {
  std::vector<Frame> out(n);
  for (Frame& f : out)
    for (int k = 0; k < 20; ++k) {
      const double y = 0.01 * k;
      f.position.push_back({0.1, y});
      f.velocity.push_back({1.0 + slope * y, 0.0});
      f.radius.push_back(0.005);
      f.mass.push_back(2650.0 * std::numbers::pi * 0.005 * 0.005);
      f.kind.push_back(0);
    }
  return out;
}

// I = gamma_dot d / sqrt(P / rho) = 2 * 0.01 / sqrt(100 / 2650); the errors of constant blocks 0.
TEST(CellRheology, GivesBackTheNumbersOfItsRows) {
  const RheologyPoint r = cell_rheology_point(rows(40), frames(8, 1.9), 4);
  ASSERT_TRUE(r.measured) << r.why_not;
  EXPECT_NEAR(r.friction, 0.3, 1e-12);
  EXPECT_NEAR(r.shear_stress, 30.0, 1e-12);
  EXPECT_NEAR(r.pressure, 100.0, 1e-12);
  EXPECT_NEAR(r.packing, 0.8, 1e-12);
  EXPECT_NEAR(r.inertial, 2.0 * 0.01 / std::sqrt(100.0 / 2650.0), 1e-12);
  EXPECT_NEAR(r.diameter, 0.01, 1e-15);
  EXPECT_NEAR(r.grain_density, 2650.0, 1e-9);
  EXPECT_NEAR(r.profile_shear_rate, 1.9, 1e-9);
  EXPECT_NEAR(r.friction_error, 0.0, 1e-12);
}

// Spheres of radius 5 mm and 2650 kg/m^3 on a column, moving at v_x = slope y (+ 1 m/s).
std::vector<Frame3> frames3(std::size_t n, double slope) {
  std::vector<Frame3> out(n);
  for (Frame3& f : out)
    for (int k = 0; k < 20; ++k) {
      const double y = 0.01 * k;
      f.position.push_back({0.1, y, 0.02});
      f.velocity.push_back({1.0 + slope * y, 0.0, 0.5});
      f.radius.push_back(0.005);
      f.mass.push_back(2650.0 * 4.0 / 3.0 * std::numbers::pi * std::pow(0.005, 3));
      f.kind.push_back(0);
    }
  return out;
}

// The same rows read as Pa with spheres: rho is a sphere's mass over its volume, the rest as above.
TEST(CellRheology, SpheresInACellGiveBackTheNumbersOfTheirRows) {
  const RheologyPoint r = cell_rheology_point(rows(40), frames3(8, 1.7), 4);
  ASSERT_TRUE(r.measured) << r.why_not;
  EXPECT_NEAR(r.friction, 0.3, 1e-12);
  EXPECT_NEAR(r.inertial, 2.0 * 0.01 / std::sqrt(100.0 / 2650.0), 1e-12);
  EXPECT_NEAR(r.grain_density, 2650.0, 1e-9);
  EXPECT_NEAR(r.diameter, 0.01, 1e-15);
  EXPECT_NEAR(r.profile_shear_rate, 1.7, 1e-9);
  EXPECT_FALSE(cell_rheology_point(rows(40), std::vector<Frame3>{}, 4).measured);
}

// Fewer rows or snapshots than the blocks need: not measured, saying how many it had.
TEST(CellRheology, TooLittleDataIsRefusedWithTheReason) {
  const RheologyPoint r = cell_rheology_point(rows(40), frames(3, 2.0), 4);
  EXPECT_FALSE(r.measured);
  EXPECT_NE(r.why_not.find("3 snapshots"), std::string::npos) << r.why_not;
  EXPECT_FALSE(cell_rheology_point(rows(7), frames(8, 2.0), 4).measured);
}

} // namespace
} // namespace talus
