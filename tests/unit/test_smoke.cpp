#include "simulation/simulation.hpp"
#include <gtest/gtest.h>
TEST(Smoke, Builds) {
  SUCCEED();
}
