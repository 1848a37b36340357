// Lees-Edwards boundaries (core/domain.hpp, docs/model.md "Lees-Edwards"): the images across y
// are where the offset puts them and move as its velocity says, a contact across the sliding side
// is the same contact as between two grains in a plain periodic box moving apart at that velocity,
// the neighbour list misses no contact while the images slide (and their offset comes back into
// the box), and threads and checkpoints change no bit.
#include <gtest/gtest.h>

#include <cmath>

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

constexpr double side = 0.3; // m

Domain sheared_box(double offset) {
  Domain d{{0.0, 0.0}, {side, side}, true, true};
  d.shear_offset = offset;
  return d;
}

// Exact in binary fractions where it matters: the cases are worked by hand (the image above sits
// `offset` further along x; one below, as far back).
TEST(LeesEdwards, TheDomainMapsAcrossTheSlidingSide) {
  const Domain d = sheared_box(0.0625);
  int heights = 0;
  Vec2 w = d.wrap({0.125, 0.3125}, &heights); // above the box: down one height, back the offset
  EXPECT_EQ(heights, 1);
  EXPECT_NEAR(w.x, 0.0625, 1e-15);
  EXPECT_NEAR(w.y, 0.0125, 1e-15);
  w = d.wrap({0.25, -0.0125}, &heights); // below: up one height, on by the offset, then wrapped
  EXPECT_EQ(heights, -1);
  EXPECT_NEAR(w.x, 0.0125, 1e-15);
  EXPECT_NEAR(w.y, 0.2875, 1e-15);
  // b's nearest image to a is the one above, at (0.15 + 0.0625, 0.31)
  const Vec2 m = d.minimum_image({0.1, 0.29}, {0.15, 0.01});
  EXPECT_NEAR(m.x, 0.1 - 0.2125, 1e-15);
  EXPECT_NEAR(m.y, -0.02, 1e-15);
  const Vec2 s = d.image_shift(-1, 1);
  EXPECT_NEAR(s.x, -side + 0.0625, 1e-15);
  EXPECT_EQ(s.y, side);
}

Material grain_material(double friction, double damping_rate) {
  return testing::cell_gas({.friction = friction, .damping_rate = damping_rate}, Cell{})
      .materials[0];
}

SimulationConfig config(double friction, int threads = 1) {
  return testing::cell_config(friction, threads);
}

// Two grains touching across the upper side, at rest. Sheared at rate g, the image of the lower
// grain slides past the upper one at g L along x: the same contact as two grains touching
// inside a plain periodic box with the lower one moving at g L. The forces are the same bits,
// and after 3000 steps (the contact has slid 9 mm, about a diameter, and the list has been built
// again across the slide) the upper grain's path and spin are the same to rounding.
TEST(LeesEdwards, AContactAcrossTheSlidingSideSeesTheImagesVelocity) {
  const double rate = 1.0, friction = 0.5;
  const auto world = [&](bool sheared) {
    World w;
    w.materials = {grain_material(friction, 50.0)};
    w.gravity = {0.0, 0.0};
    w.domain = {{0.0, 0.0}, {side, side}, true, true};
    w.add_particle({.position = {0.15, side - 0.0049}, .radius = 0.005});
    // plain periodic: the lower grain where the image would be, moving as it would
    w.add_particle({.position = {0.15, sheared ? 0.0049 : side + 0.0049 - side},
                    .radius = 0.005,
                    .velocity = {sheared ? 0.0 : rate * side, 0.0}});
    if (sheared) {
      Driver d;
      d.motion = Cell{.shear_rate = rate};
      w.drivers.push_back(d);
    }
    return w;
  };
  Simulation le(world(true), config(friction));
  Simulation plain(world(false), config(friction));
  EXPECT_EQ(le.world().particles.force[0].x, plain.world().particles.force[0].x);
  EXPECT_EQ(le.world().particles.force[0].y, plain.world().particles.force[0].y);
  EXPECT_GT(le.world().particles.force[0].x, 0.0); // dragged along by the sliding image
  le.run(3000);
  plain.run(3000);
  const Particles& a = le.world().particles;
  const Particles& b = plain.world().particles;
  EXPECT_NEAR(a.position[0].x, b.position[0].x, 1e-12);
  EXPECT_NEAR(a.position[0].y, b.position[0].y, 1e-12);
  EXPECT_NEAR(a.angular_velocity[0], b.angular_velocity[0], 1e-9);
  EXPECT_NEAR(le.world().domain.shear_offset, rate * side * le.time(), 1e-12);
  EXPECT_GT(le.neighbours().builds, 1u);
}

// Two grains at rest, the upper one 27 mm along x from where the image of the lower one will
// pass it: the slide alone brings them into contact, nothing else moves, and only the offset's
// change in the list's reserve (Simulation::update_cell_reserve) rebuilds the list in time. At
// every step the list holds the contact exactly while the grains touch.
TEST(LeesEdwards, TheSlideAloneRebuildsTheListInTime) {
  World w;
  w.materials = {grain_material(0.0, 0.0)};
  w.gravity = {0.0, 0.0};
  w.domain = {{0.0, 0.0}, {side, side}, true, true};
  w.add_particle({.position = {0.15, side - 0.0049}, .radius = 0.005});
  w.add_particle({.position = {0.123, 0.0049}, .radius = 0.005});
  Driver d;
  d.motion = Cell{.shear_rate = 10.0}; // the image slides at 3 m/s
  w.drivers.push_back(d);
  Simulation s(std::move(w), config(0.0));
  int touching = 0;
  for (int n = 0; n < 1500; ++n) {
    s.run(1);
    const auto want = touching_pairs(s);
    ASSERT_EQ(listed_contacts(s), want) << "at step " << s.step_count();
    touching += !want.empty();
  }
  EXPECT_GT(touching, 10);
}

// per_row^2 disks of radius `radius` to 1.5 mm more on a jittered lattice in a sheared box, in
// the shear's flow, v_x = rate (y - L/2) (or at rest: `flow` false), with a random part of up
// to `speed`.
World sheared_gas(int per_row, double speed, double friction, Cell cell, double damping_rate,
                  double offset, double radius = 0.004, bool flow = true) {
  return testing::cell_gas({.per_row = per_row,
                            .side = side,
                            .speed = speed,
                            .friction = friction,
                            .damping_rate = damping_rate,
                            .radius = radius,
                            .spread = 0.0015,
                            .flow = flow,
                            .seed = 17},
                           cell, offset);
}

// A dense gas (packing fraction about 0.45) of undamped frictionless grains at rest sheared
// fast: the images slide by 2 m/s, a skin in a few dozen steps (the top row is moved up so that
// the images of the bottom row meet it), and the offset starts a few millimetres short of the
// width, so that it comes back into the box at an early build. Every 10 steps (3000 in all) the
// contacts the list holds are every touching pair at the nearest image (Domain::minimum_image),
// and every force is the sum of their springs to rounding. Without the offset in the grid's
// search across the side (neighbour_list.cpp, collect_row) pairs across the side are missed.
TEST(LeesEdwards, TheNeighbourListMissesNoContactWhileTheImagesSlide) {
  const double rate = 2.0 / side, k = 1.0e5;
  SimulationConfig c = config(0.0);
  c.integrator = Integrator::verlet;
  World w = sheared_gas(20, 0.0, 0.0, Cell{.shear_rate = rate}, 0.0, side - 0.004, 0.005, false);
  for (Vec2& r : w.particles.position) // the top row 4 mm nearer the bottom row's images
    if (r.y > side - side / 20) r.y += 0.004;
  Simulation s(std::move(w), c);
  std::size_t across = 0; // contacts seen across the upper side
  bool wrapped = false;
  for (int n = 0; n < 300; ++n) {
    s.run(10);
    wrapped = wrapped || s.world().domain.shear_offset < side / 2;
    const auto want = touching_pairs(s);
    ASSERT_EQ(listed_contacts(s), want) << "at step " << s.step_count();
    s.for_each_contact([&](const ContactView& v) {
      const Particles& p = s.world().particles;
      across += std::abs(p.position[v.i].y - p.position[v.j].y) > side / 2;
    });
    const std::vector<Vec2> f = spring_forces(s, k);
    for (std::size_t i = 0; i < f.size(); ++i) // 1e-9 of a force of an overlap of 1% of r
      ASSERT_LT(norm(s.world().particles.force[i] - f[i]), 1e-9 * k * 5e-5)
          << "grain " << i << " at step " << s.step_count();
  }
  EXPECT_TRUE(wrapped);
  EXPECT_GT(across, 100u);
  EXPECT_GT(s.neighbours().builds, 20u);
}

// Frictional grains sheared at a normal stress: 1 and 2 threads, and a run saved to a
// checkpoint's bytes halfway and restored, give the same bits.
TEST(LeesEdwards, ThreadsAndCheckpointsChangeNoBit) {
  const Cell cell{.pressure = 50.0, .max_strain_rate = 3.0, .relaxation = 0.5, .shear_rate = 5.0};
  const auto start = [&](int threads) {
    return Simulation(sheared_gas(16, 0.2, 0.3, cell, 50.0, 0.0), config(0.3, threads));
  };
  Simulation one = start(1);
  one.run(6'000);
  Simulation two = start(2);
  two.run(6'000);
  EXPECT_EQ(state_hash(two), state_hash(one));
  Simulation first = start(1);
  first.run(3'000);
  const Checkpoint saved{first.state(), first.config(), ""};
  Checkpoint back = decode_checkpoint(encode_checkpoint(saved), "memory");
  Simulation resumed = Simulation::restore(std::move(back.state), back.config);
  resumed.run(3'000);
  EXPECT_EQ(state_hash(resumed), state_hash(one));
  EXPECT_NEAR(resumed.cell_driver()->shear_strain, 5.0 * 6'000 * 1e-5, 1e-12);
  EXPECT_GT(one.world().domain.shear_offset, 0.0);
}

// Frictional grains sheared at a normal stress: the controller's reading of sigma_yy is the
// stress measure's (region_stress over the cell: the forces from the laws, the branches, the
// kinetic part) to rounding, the height alone having moved.
TEST(LeesEdwards, TheControllerReadsTheNormalStressTheMeasureSees) {
  const Cell cell{.pressure = 50.0, .max_strain_rate = 3.0, .relaxation = 0.5, .shear_rate = 5.0};
  Simulation s(sheared_gas(16, 0.2, 0.3, cell, 50.0, 0.0), config(0.3));
  s.run(20'000);
  const Domain& d = s.world().domain;
  const RegionStress measured = region_stress(s, d.lo, d.hi);
  EXPECT_NEAR(s.cell_reading().pressure, measured.total()(1, 1), 1e-9 * 50.0);
  EXPECT_GT(measured.total()(1, 1), 10.0); // pressing towards its 50 N/m (SimpleShear.* holds it)
  EXPECT_LT(s.world().domain.size().y, side); // by the height alone
  EXPECT_EQ(s.world().domain.size().x, side);
}

// Box keys that cannot shear are refused with the reason.
TEST(LeesEdwards, ACellThatCannotShearIsRefused) {
  World w = sheared_gas(4, 0.0, 0.0, Cell{.shear_rate = 1.0}, 0.0, 0.0);
  w.domain.periodic_y = false;
  try {
    Simulation s(std::move(w), config(0.0));
    ADD_FAILURE() << "a shear along an open y was taken";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("periodic in x and y"), std::string::npos) << e.what();
  }
  World v = sheared_gas(4, 0.0, 0.0, Cell{.strain_rate = {1.0, 0.0}, .shear_rate = 1.0}, 0.0, 0.0);
  EXPECT_THROW(Simulation(std::move(v), config(0.0)), InvalidArgument);
}

} // namespace
} // namespace talus
