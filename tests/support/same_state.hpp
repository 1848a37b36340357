#pragma once
// Bit-for-bit comparison of two simulations: everything that determines how a run goes on.
#include <gtest/gtest.h>

#include <vector>

#include "simulation/simulation.hpp"

namespace talus::testing {

template <class T> void expect_equal(const std::vector<T>& a, const std::vector<T>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a[k], b[k]) << k;
}

/// `history`: also the lists' springs (a specialised step of a history-free law keeps none, where
/// the general step keeps zeros).
inline void expect_same_state(const Simulation& a, const Simulation& b, bool history = true) {
  EXPECT_EQ(a.step_count(), b.step_count());
  EXPECT_EQ(a.time(), b.time());
  EXPECT_EQ(a.renumberings(), b.renumberings());
  const Particles& p = a.world().particles;
  const Particles& q = b.world().particles;
  expect_equal(p.id, q.id);
  expect_equal(p.position, q.position);
  expect_equal(p.velocity, q.velocity);
  expect_equal(p.angle, q.angle);
  expect_equal(p.angular_velocity, q.angular_velocity);
  expect_equal(p.force, q.force);
  expect_equal(p.torque, q.torque);
  expect_equal(p.force_previous, q.force_previous);
  expect_equal(p.torque_previous, q.torque_previous);
  expect_equal(p.gear.r2, q.gear.r2);
  expect_equal(p.gear.r3, q.gear.r3);
  expect_equal(p.gear.r4, q.gear.r4);
  expect_equal(p.gear.phi4, q.gear.phi4);
  const NeighbourList& l = a.neighbours();
  const NeighbourList& m = b.neighbours();
  EXPECT_EQ(l.builds, m.builds);
  expect_equal(l.neighbour, m.neighbour);
  if (history) {
    expect_equal(l.history, m.history);
    expect_equal(l.wall_history, m.wall_history);
    expect_equal(l.rolling, m.rolling);
    expect_equal(l.wall_rolling, m.wall_rolling);
  }
  expect_equal(l.reference, m.reference);
}

} // namespace talus::testing
