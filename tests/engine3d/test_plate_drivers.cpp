// Driven plates in 3D (engine3d/plate_drivers.hpp): each motion puts its plate where its closed
// form has it, with the velocity field that is the motion's time derivative; a sphere on a floor
// vibrating along gravity stays on it below one g of the floor's acceleration and leaves it
// above (the bouncing ball's threshold, Gamma = A (2 pi f)^2 / g = 1); a driver that cannot be
// is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine3d/simulation3.hpp"
#include "support/two_body.hpp"
#include "talus/error.hpp"

namespace talus {
namespace {

// A point of the plate, given by its coordinates along the plate's axes.
Vec3 point_of(const Plane& p, double u, double v) {
  return p.centre + u * p.axis_u + v * p.axis_v();
}

// The velocity field of each motion is the derivative of its points' motion: a central
// difference over a short step, whose own error is second order in the step; the bound is that
// error's size, far below the speeds a wrong field would be off by.
TEST(PlateDrivers, EachMotionsVelocityIsItsPointsRateOfMotion) {
  const Plane start = make_plane({0.1, 0.2, 0.3}, {0.2, -0.3, 1.0}, 0.05, 0.02);
  std::vector<PlateDriver> drivers(3);
  drivers[0] = {.plate = 0, .motion = PlateDriver::Motion::translate, .velocity = {0.3, -0.1, 0.2}};
  drivers[1] = {.plate = 1,
                .motion = PlateDriver::Motion::vibrate,
                .direction = {0.0, 1.0, 1.0},
                .amplitude = 2e-3,
                .frequency = 30.0,
                .phase = 0.4};
  drivers[2] = {.plate = 2,
                .motion = PlateDriver::Motion::rotate,
                .pivot = {0.0, 0.1, 0.0},
                .angular_velocity = {1.0, -2.0, 0.5}};
  const std::vector<PlatePose> poses(3, {start.centre, start.normal, start.axis_u});
  const auto at = [&](double t) {
    std::vector<Plane> plates(3, start);
    drive_plates(plates, drivers, poses, t);
    return plates;
  };
  const double t = 0.37, h = 1e-6;
  const auto now = at(t), before = at(t - h), after = at(t + h);
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec3 x = point_of(now[k], 0.01, -0.015);
    const Vec3 rate =
        (1.0 / (2.0 * h)) * (point_of(after[k], 0.01, -0.015) - point_of(before[k], 0.01, -0.015));
    EXPECT_LT(norm(now[k].velocity_at(x) - rate), 1e-6 * norm(rate)) << "driver " << k;
    EXPECT_NEAR(norm(now[k].normal), 1.0, 1e-15);
  }
  // and where they are: the closed forms
  EXPECT_LT(norm(now[0].centre - (start.centre + t * drivers[0].velocity)), 1e-15);
  const double lift = 2e-3 * std::sin(2.0 * std::numbers::pi * 30.0 * t + 0.4) / std::sqrt(2.0);
  EXPECT_LT(norm(now[1].centre - (start.centre + Vec3{0.0, lift, lift})), 1e-15);
  const double turned = std::acos(dot(now[2].normal, start.normal));
  EXPECT_GT(turned, 0.1); // the normal turned (by at most the angle turned, 0.84 rad)
  EXPECT_LT(turned, 0.84);
}

// A sphere resting on a floor that vibrates vertically: Gamma steps of contact lost.
std::size_t steps_off_the_floor(double gamma) {
  const double g = 9.81, f = 20.0, w = 2.0 * std::numbers::pi * f, r = 2e-3;
  Material m = testing::elastic_material(1e5);
  m.restitution = 0.3;
  Scene3 scene;
  scene.materials = {m};
  scene.gravity = {0.0, 0.0, -g};
  scene.plates.push_back(make_plane({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}));
  scene.drivers.push_back({.plate = 0,
                           .motion = PlateDriver::Motion::vibrate,
                           .direction = {0.0, 0.0, 1.0},
                           .amplitude = gamma * g / (w * w),
                           .frequency = f});
  const double mass = shape_mass(Shape::sphere, r, m.density);
  // at rest on the floor, moving with it (the floor starts upward at A w)
  scene.add_sphere({.position = {0.0, 0.0, r - mass * g / m.normal_stiffness},
                    .radius = r,
                    .velocity = {0.0, 0.0, gamma * g / w}});
  Simulation3 s(std::move(scene), {.timestep = 1e-5});
  std::size_t off = 0;
  for (int k = 0; k < 20000; ++k) { // four periods
    s.step();
    off += s.contact_count() == 0 ? 1 : 0;
  }
  return off;
}

TEST(PlateDrivers, ASphereOnAVibratingFloorLeavesItAboveOneG) {
  EXPECT_EQ(steps_off_the_floor(0.5), 0u);
  EXPECT_GT(steps_off_the_floor(2.0), 1000u);
}

TEST(PlateDrivers, ADriverThatCannotBeIsRefused) {
  std::vector<Plane> plates(2, make_plane({}, {0.0, 0.0, 1.0}));
  EXPECT_THROW(validate({{.plate = 2}}, plates.size()), InvalidArgument);
  EXPECT_THROW(validate({{.plate = 1}, {.plate = 1}}, plates.size()), InvalidArgument);
  EXPECT_THROW(
      validate({{.plate = 0, .motion = PlateDriver::Motion::vibrate, .direction = {0.0, 0.0, 0.0}}},
               plates.size()),
      InvalidArgument);
  EXPECT_NO_THROW(validate({{.plate = 0}, {.plate = 1}}, plates.size()));
}

} // namespace
} // namespace talus
