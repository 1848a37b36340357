// The servo controller of a wall held at a load (drivers/servo.hpp), on the model its rule is
// derived from: the wall's contacts as a spring k and a dashpot c against grains that stand
// still, so that the load is k x + c v for the wall at x moving at v.
#include <gtest/gtest.h>

#include <cmath>

#include "drivers/servo.hpp"

namespace talus {
namespace {

constexpr double servo_dt = 1e-6;    // s
constexpr double servo_k = 1e5;      // N/m
constexpr double servo_target = 2.0; // N
constexpr double servo_fast = 1.0e6; // m/s: a speed limit that never binds here

Servo servo(double relaxation, double max_speed = servo_fast) {
  Servo s;
  s.force = servo_target;
  s.max_speed = max_speed;
  s.relaxation = relaxation;
  return s;
}

// The load of the still grains for the wall where the servo has put it.
double load(const Servo& s, double c) {
  return servo_k * s.displacement + c * s.speed;
}

TEST(ServoController, MovesAtItsSpeedLimitUntilItTouches) {
  Servo s = servo(0.5, 0.3);
  EXPECT_EQ(servo_speed(s, {}, servo_dt), 0.3);
  s.force = -1.0; // pulled: away from the grains
  EXPECT_EQ(servo_speed(s, {}, servo_dt), -0.3);
  s.force = 0.0;
  EXPECT_EQ(servo_speed(s, {}, servo_dt), 0.0);
  // touching, a large error: no faster than the limit
  s.force = servo_target;
  EXPECT_EQ(servo_speed(s, {.load = 0.0, .stiffness = servo_k, .damping = 0.0}, servo_dt), 0.3);
  EXPECT_EQ(servo_speed(s, {.load = 1e3, .stiffness = servo_k, .damping = 0.0}, servo_dt), -0.3);
}

// Each step closes the fraction alpha of the error, whatever the dashpots: after n steps the
// error is (1 - alpha)^n of the first, to rounding (a relative 1e-12 of the target over the
// steps' sums), and the wall never reverses (no overshoot for alpha <= 1).
TEST(ServoController, ClosesTheAskedFractionOfTheErrorPerStep) {
  for (const double c :
       {0.0, 0.1 * servo_k * servo_dt, 10.0 * servo_k * servo_dt, 1000.0 * servo_k * servo_dt}) {
    for (const double alpha : {0.1, 0.5, 1.0}) {
      Servo s = servo(alpha);
      double error = servo_target;
      for (int n = 0; n < 30; ++n) {
        servo_advance(s, {.load = load(s, c), .stiffness = servo_k, .damping = c}, servo_dt);
        error *= 1.0 - alpha;
        EXPECT_NEAR(servo_target - load(s, c), error, 1e-12 * servo_target)
            << "c " << c << " alpha " << alpha;
        EXPECT_GE(s.speed, 0.0);
      }
    }
  }
}

// Why the rule counts the dashpots: PFC's plain rule, v = alpha (F_target - F) / (K dt), is the
// same rule told there are none. Beside dashpots of ten steps' damping time the load's error
// then grows step by step, its sign flipping, where the rule with them closes it.
TEST(ServoController, ThePlainRuleOscillatesBesideDashpots) {
  const double c = 10.0 * servo_k * servo_dt;
  Servo plain = servo(0.5), full = servo(0.5);
  for (int n = 0; n < 20; ++n) {
    servo_advance(plain, {.load = load(plain, c), .stiffness = servo_k, .damping = 0.0}, servo_dt);
    servo_advance(full, {.load = load(full, c), .stiffness = servo_k, .damping = c}, servo_dt);
  }
  EXPECT_GT(std::abs(servo_target - load(plain, c)), 10.0 * servo_target);
  EXPECT_LT(std::abs(servo_target - load(full, c)), 1e-5 * servo_target);
}

} // namespace
} // namespace talus
