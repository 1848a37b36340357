// Janssen's wall stress (post/janssen.hpp) on silos made to order: wall contacts laid out along
// the closed form, whose fit must give back its saturation and length; a column without wall
// friction, which has no saturation; and the force balance of the fit's prediction.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/frame.hpp"
#include "post/janssen.hpp"
#include "talus/error.hpp"

namespace talus {
namespace {

constexpr double janssen_W = 0.1, janssen_H = 0.6, janssen_r = 0.0025, janssen_m = 1.0e-4,
                 janssen_g = 9.81;

// Free grains filling the silo [0, W] x [0, H] on a square lattice, and on each wall a contact
// every `pitch` of depth whose normal force is sigma(z) pitch and whose friction is mu times
// that: the wall stress of the closed form.
Frame silo(double saturation, double length, double mu, double pitch) {
  Frame f;
  for (double y = janssen_r; y < janssen_H; y += 2.0 * janssen_r)
    for (double x = janssen_r; x < janssen_W; x += 2.0 * janssen_r) {
      f.position.push_back({x, y});
      f.radius.push_back(janssen_r);
      f.mass.push_back(janssen_m);
      f.kind.push_back(0);
    }
  const double top = f.position.back().y + janssen_r; // the lattice's highest grain top
  for (double z = 0.5 * pitch; z < top; z += pitch)
    for (const double wall : {0.0, janssen_W}) {
      Frame::Chain c;
      c.point = {wall, top - z};
      const double normal = janssen_stress(saturation, length, z) * pitch;
      c.force_on_from = {wall == 0.0 ? normal : -normal, mu * normal};
      c.has_vector = true;
      c.from_free = true;
      c.to_free = false;
      f.chains.push_back(c);
    }
  return f;
}

JanssenOptions options() {
  JanssenOptions o;
  o.right = janssen_W;
  o.gravity = janssen_g;
  return o;
}

// The fit gives back sigma_inf and lambda within 1%: each bin's stress is the mean of the closed
// form over the bin rather than its value at the centre, a bias of order (bin / lambda)^2 / 24,
// 0.3% here; the mobilised friction is the mu laid out, to rounding.
TEST(Janssen, TheFitGivesBackTheClosedForm) {
  const double saturation = 15.0, length = 0.15, mu = 0.4;
  const Frame f = silo(saturation, length, mu, 1e-3);
  const JanssenProfile p = janssen_profile({f}, options());
  ASSERT_TRUE(p.measured) << p.why_not;
  EXPECT_NEAR(p.saturation, saturation, 0.01 * saturation);
  EXPECT_NEAR(p.length, length, 0.01 * length);
  EXPECT_NEAR(p.mobilised_friction, mu, 1e-12);
  EXPECT_NEAR(p.surface, janssen_H, 1e-12);
  EXPECT_NEAR(p.base, 0.0, 1e-12);
  // the bed's weight per area: the lattice's mass over W H
  EXPECT_NEAR(p.weight_density,
              static_cast<double>(f.position.size()) * janssen_m * janssen_g /
                  (janssen_W * janssen_H),
              1e-9);
  EXPECT_NEAR(p.predicted_saturation, p.weight_density * janssen_W / (2.0 * mu), 1e-9);
  EXPECT_NEAR(p.stress_ratio, janssen_W / (2.0 * mu * p.length), 1e-12);
  EXPECT_LT(p.saturation_error, 0.01 * saturation);
}

// Wall stress growing in proportion to depth all the way down (lambda far beyond the bed) does
// not saturate: no fit is claimed.
TEST(Janssen, AColumnThatDoesNotSaturateIsNotFitted) {
  const JanssenProfile p = janssen_profile({silo(1e4, 1e3, 0.1, 1e-3)}, options());
  EXPECT_FALSE(p.measured);
  EXPECT_NE(p.why_not.find("saturation"), std::string::npos) << p.why_not;
}

TEST(Janssen, ASiloWithoutWallContactsIsRefused) {
  Frame f = silo(15.0, 0.15, 0.4, 1e-3);
  f.chains.clear();
  EXPECT_THROW(janssen_profile({f}, options()), InvalidArgument);
}

} // namespace
} // namespace talus
