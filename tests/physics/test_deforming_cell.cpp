// The deforming periodic cell (drivers/cell.hpp, docs/model.md "Deforming cell"): the box and
// the grains follow a set strain rate exactly, the neighbour list misses no contact however fast
// the cell shrinks, a cell held at a pressure reaches it as an independent stress measure
// (analysis/stress.hpp) sees it, and threads and checkpoints change no bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "analysis/stress.hpp"
#include "io/checkpoint.hpp"
#include "simulation/simulation.hpp"
#include "support/cell_gas.hpp"
#include "support/contact_check.hpp"
#include "support/state_hash.hpp"

namespace talus {
namespace {

using testing::listed_contacts;
using testing::spring_forces;
using testing::state_hash;
using testing::touching_pairs;

constexpr double cell_side = 0.3; // m, the box at the start

// per_row^2 disks of radius 4 to 6 mm on a jittered lattice in a box periodic in x and y, moving
// at up to `speed` m/s, with the linear law's damping rate (1/s), and a cell driver with `cell`'s
// keys.
World gas(int per_row, double speed, double friction, Cell cell, double damping_rate = 50.0) {
  return testing::cell_gas({.per_row = per_row,
                            .side = cell_side,
                            .speed = speed,
                            .friction = friction,
                            .damping_rate = damping_rate},
                           cell);
}

SimulationConfig config(double friction, int threads = 1) {
  return testing::cell_config(friction, threads);
}

// Grains at rest that never meet: after n steps the box's sides are L0 exp(rate t) and every
// grain sits where the affine map takes it, x = lo + (x0 - lo) exp(rate t). The tolerance is
// rounding: each step multiplies by exp(rate dt) once more, a few units in the last place each.
TEST(DeformingCell, ARateScalesTheBoxAndTheGrainsAffinely) {
  const Vec2 rate{-0.8, 0.5};
  World w = gas(10, 0.0, 0.0, Cell{.strain_rate = rate});
  const std::vector<Vec2> start = w.particles.position;
  Simulation s(std::move(w), config(0.0));
  s.run(20'000);
  const double t = s.time();
  const Vec2 f{std::exp(rate.x * t), std::exp(rate.y * t)};
  const Domain& d = s.world().domain;
  EXPECT_NEAR(d.size().x, cell_side * f.x, 1e-12 * cell_side);
  EXPECT_NEAR(d.size().y, cell_side * f.y, 1e-12 * cell_side);
  const Particles& p = s.world().particles;
  double worst = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 want = d.lo + Vec2{start[p.id[i]].x * f.x, start[p.id[i]].y * f.y};
    worst = std::max(worst, norm(d.minimum_image(p.position[i], want)));
  }
  EXPECT_LT(worst, 1e-12 * cell_side);
  EXPECT_NEAR(s.cell_driver()->strain.x, rate.x * t, 1e-12);
}

// Grains at rest squeezed from a packing fraction of 0.3 to 0.7 in 0.012 s (in six contact
// times: a violent compression, so that the strain, not the grains' own moves, closes the gaps).
// At every 10th step the contacts the list holds are every touching pair, and the force on each
// grain (velocity Verlet: the force of the positions after the step) is the sum of their springs
// to rounding. Without the strain's reserve (Simulation::update_cell_reserve) in the drift test,
// pairs are missed; without it in the contact candidates' bound alone, forces are.
TEST(DeformingCell, TheNeighbourListMissesNoContactWhileTheCellShrinks) {
  const double rate = 0.5 * std::log(0.3 / 0.7) / 0.012, k = 1.0e5;
  SimulationConfig c = config(0.0);
  c.integrator = Integrator::verlet;
  Simulation s(gas(20, 0.0, 0.0, Cell{.strain_rate = {rate, rate}}, 0.0), c);
  std::size_t most = 0;
  for (int n = 0; n < 120; ++n) {
    s.run(10);
    const auto want = touching_pairs(s);
    ASSERT_EQ(listed_contacts(s), want) << "at step " << s.step_count();
    most = std::max(most, want.size());
    const std::vector<Vec2> f = spring_forces(s, k);
    for (std::size_t i = 0; i < f.size(); ++i) // 1e-9 of a force of an overlap of 1% of r
      ASSERT_LT(norm(s.world().particles.force[i] - f[i]), 1e-9 * k * 5e-5)
          << "grain " << i << " at step " << s.step_count();
  }
  EXPECT_GT(most, 300u); // the contacts came, with the density
  EXPECT_GT(s.neighbours().builds, 5u);
}

// Frictionless disks compressed to 100 N/m from a packing fraction of 0.5: the pressure an
// independent measure computes (region_stress: the forces from the laws, the contacts' branch
// vectors, the kinetic part) is the target to 0.5%. Not closer: the packing still creeps as its
// grains rearrange, and the controller answers a rearrangement a step after it; over the next
// 0.4 s the pressure stays within 0.03% of the target while the box shrinks by a further 1%.
// The controller's own reading is the same sum as the measure: to rounding.
TEST(DeformingCell, APressureIsHeldAsTheStressMeasureSeesIt) {
  const double target = 100.0; // N/m: a mean overlap of about p d / k = 1e-4 of the diameter
  Simulation s(
      gas(22, 0.0, 0.0, Cell{.pressure = target, .max_strain_rate = 2.0, .relaxation = 0.5}),
      config(0.0));
  s.run(40'000);
  const Domain& d = s.world().domain;
  const RegionStress measured = region_stress(s, d.lo, d.hi);
  const double pressure = 0.5 * measured.total().trace();
  EXPECT_NEAR(pressure, target, 5e-3 * target);
  EXPECT_NEAR(s.cell_reading().pressure, pressure, 1e-9 * target);
  EXPECT_GT(s.cell_reading().stiffness, 0.0);
  EXPECT_LT(d.size().x, 0.9 * cell_side); // it shrank to get there
  EXPECT_EQ(d.size().x, d.size().y);      // isotropically
}

// A cell held at a pressure with friction: 1 and 2 threads, and a run saved to a checkpoint's
// bytes halfway and restored, give the same bits.
TEST(DeformingCell, ThreadsAndCheckpointsChangeNoBit) {
  const Cell cell{.pressure = 50.0, .max_strain_rate = 3.0, .relaxation = 0.5};
  const auto run = [&](int threads) {
    Simulation s(gas(16, 0.2, 0.3, cell), config(0.3, threads));
    s.run(6'000);
    return state_hash(s);
  };
  const std::uint64_t one = run(1);
  EXPECT_EQ(run(2), one);
  Simulation first(gas(16, 0.2, 0.3, cell), config(0.3));
  first.run(3'000);
  const Checkpoint saved{first.state(), first.config(), ""};
  Checkpoint back = decode_checkpoint(encode_checkpoint(saved), "memory");
  Simulation resumed = Simulation::restore(std::move(back.state), back.config);
  resumed.run(3'000);
  EXPECT_EQ(state_hash(resumed), one);
  EXPECT_GT(resumed.cell_driver()->strain.x, -1.0);
  EXPECT_LT(resumed.cell_driver()->strain.x, 0.0);
}

// A cell that shrinks the box below the three interaction ranges the list's grid needs stops
// the run with the cause named, not a grid error alone.
TEST(DeformingCell, ABoxShrunkTooFarStopsTheRunNamingTheCell) {
  Simulation s(gas(2, 0.0, 0.0, Cell{.strain_rate = {-3.0, -3.0}}), config(0.0));
  try {
    s.run(100'000);
    ADD_FAILURE() << "the box shrank to " << s.world().domain.size().x << " m unnoticed";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("the deforming cell shrank the box"), std::string::npos)
        << e.what();
  }
}

// What the remap would leave behind is refused, as are keys that do not fit the box.
TEST(DeformingCell, WhatCannotFollowTheCellIsRefused) {
  World walls = gas(4, 0.0, 0.0, Cell{.strain_rate = {-1.0, -1.0}});
  walls.add_wall({0.0, 0.0}, {cell_side, 0.0});
  EXPECT_THROW(Simulation(std::move(walls), config(0.0)), InvalidArgument);
  World open = gas(4, 0.0, 0.0, Cell{.strain_rate = {-1.0, -1.0}});
  open.domain.periodic_y = false;
  EXPECT_THROW(Simulation(std::move(open), config(0.0)), InvalidArgument);
  World unbounded = gas(4, 0.0, 0.0, Cell{.pressure = 10.0});
  EXPECT_THROW(Simulation(std::move(unbounded), config(0.0)), InvalidArgument); // no max rate
  World two = gas(4, 0.0, 0.0, Cell{.strain_rate = {-1.0, 0.0}});
  two.drivers.push_back(two.drivers.front());
  EXPECT_THROW(Simulation(std::move(two), config(0.0)), InvalidArgument);
}

} // namespace
} // namespace talus
