// The native engine's velocity Verlet with LAMMPS' convention (verlet_velocity = half_step: the
// contact laws see the half-step velocity, as under fix nve/sphere) against LAMMPS with
// pair_style granthesis: two disks through a whole collision, oblique, sliding and spinning, for
// both normal laws, agree to rounding. With the native default (the predicted velocity) they
// differ at first order in dt, which is the convention, not an error (docs/validation.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "two_disks.hpp"

namespace talus::lammps_test {
namespace {

struct Difference {
  double position = 0.0; ///< the largest |dx|, |dy| over both disks, m
  double velocity = 0.0; ///< the largest |dv|, m/s
  double spin = 0.0;     ///< the largest |d omega|, rad/s
};

// The largest differences of the disks' positions, velocities and spins between the engines.
Difference between(LammpsInstance& l, const Simulation& s) {
  const Particles& p = s.world().particles;
  Difference d;
  for (int k = 0; k < static_cast<int>(p.size()); ++k) {
    const auto i = static_cast<std::size_t>(k);
    d.position = std::max({d.position, std::abs(l.position(k + 1)[0] - p.position[i].x),
                           std::abs(l.position(k + 1)[1] - p.position[i].y)});
    d.velocity = std::max({d.velocity, std::abs(l.velocity(k + 1)[0] - p.velocity[i].x),
                           std::abs(l.velocity(k + 1)[1] - p.velocity[i].y)});
    d.spin =
        std::max(d.spin, std::abs(l.lmp()->atom->omega[l.index(k + 1)][2] - p.angular_velocity[i]));
  }
  return d;
}

// Whether LAMMPS may run with newton on: not with a spring, tangential or rolling, which fix
// granthesis/history keeps.
bool newton_allowed(const std::string& tangential, const Material& m) {
  return !keeps_history(parse_tangential_law(tangential)) && m.rolling_friction == 0.0;
}

// Both engines from the same two disks of material m, `steps` steps of dt.
Difference after(const std::string& normal, const std::string& tangential,
                 VerletVelocity convention, const std::vector<Disk>& disks, double dt, int steps,
                 const Material& m = grains()) {
  LammpsInstance l;
  set_up(l, normal + " " + tangential, m, disks, newton_allowed(tangential, m), dt);
  l.commands(
      {"fix move all nve/sphere disc", "fix plane all enforce2d", "run " + std::to_string(steps)});
  Simulation s = native(normal, tangential, m, disks, dt, convention);
  s.run(static_cast<std::uint64_t>(steps));
  return between(l, s);
}

// Two disks 0.2 um apart, closing at 0.2 m/s, 1.5 mm off centre, one spinning: the contact
// slides, sticks and ends within the 3000 steps (the contact lasts several hundred of them).
std::vector<Disk> oblique_pair() {
  const double reach = 0.005 + 0.004 + 2e-7, offset = 0.0015;
  return {{{0.0, 0.0}, {0.1, 0.0}, 0.005, 2.0e-4, 30.0},
          {{std::sqrt(reach * reach - offset * offset), offset}, {-0.1, 0.0}, 0.004, 1.5e-4, 0.0}};
}

TEST(VerletAgreement, HalfStepConventionReproducesLammpsToRounding) {
  for (const std::string normal : {"linear", "hertz"}) {
    SCOPED_TRACE(normal);
    const Difference same =
        after(normal, "coulomb", VerletVelocity::half_step, oblique_pair(), 1e-7, 3000);
    const Difference other =
        after(normal, "coulomb", VerletVelocity::predicted, oblique_pair(), 1e-7, 3000);
    std::printf("%s: half_step differs by %.2e m, %.2e m/s, %.2e rad/s; predicted by %.2e m, "
                "%.2e m/s, %.2e rad/s\n",
                normal.c_str(), same.position, same.velocity, same.spin, other.position,
                other.velocity, other.spin);
    // rounding: the engines order a few operations differently (the kick's 1/m, gravity's sum),
    // a few ulp per step over 3000 steps: below 1e-12 of the speeds, 1e-15 m of the positions
    EXPECT_LT(same.position, 1e-15);
    EXPECT_LT(same.velocity, 1e-12 * 0.1);
    EXPECT_LT(same.spin, 1e-12 * 30.0);
    // the other convention: a difference of first order in dt, far above rounding
    EXPECT_GT(other.velocity, 1e3 * same.velocity + 1e-12);
  }
}

// The spring laws: the springs kept by fix granthesis/history in LAMMPS, beside the native list's,
// through the same sliding and sticking contact. Rounding as above.
TEST(VerletAgreement, SpringLawsAgreeToRounding) {
  for (const std::string normal : {"linear", "hertz"})
    for (const std::string tangential : {"cundall_strack", "mindlin"}) {
      SCOPED_TRACE(normal + " " + tangential);
      const Difference d =
          after(normal, tangential, VerletVelocity::half_step, oblique_pair(), 1e-7, 3000);
      std::printf("%s %s: %.2e m, %.2e m/s, %.2e rad/s\n", normal.c_str(), tangential.c_str(),
                  d.position, d.velocity, d.spin);
      EXPECT_LT(d.position, 1e-15);
      EXPECT_LT(d.velocity, 1e-12 * 0.1);
      EXPECT_LT(d.spin, 1e-12 * 30.0);
    }
}

// Rolling resistance: its springs kept by a second fix granthesis/history in LAMMPS, beside the
// native list's, through the same contact, with a tangential law with and without a spring.
// Rounding as above; without rolling resistance in one engine the spins would differ at once.
TEST(VerletAgreement, RollingResistanceAgreesToRounding) {
  Material m = grains();
  m.rolling_friction = 0.3;
  for (const std::string normal : {"linear", "hertz"})
    for (const std::string tangential : {"coulomb", "cundall_strack"}) {
      SCOPED_TRACE(normal + " " + tangential);
      const Difference d =
          after(normal, tangential, VerletVelocity::half_step, oblique_pair(), 1e-7, 3000, m);
      std::printf("rolling, %s %s: %.2e m, %.2e m/s, %.2e rad/s\n", normal.c_str(),
                  tangential.c_str(), d.position, d.velocity, d.spin);
      EXPECT_LT(d.position, 1e-15);
      EXPECT_LT(d.velocity, 1e-12 * 0.1);
      EXPECT_LT(d.spin, 1e-12 * 30.0);
    }
  // and the native rolling resistance changes the spins far beyond rounding
  Simulation with = native("hertz", "coulomb", m, oblique_pair(), 1e-7, VerletVelocity::half_step);
  Simulation without =
      native("hertz", "coulomb", grains(), oblique_pair(), 1e-7, VerletVelocity::half_step);
  with.run(3000);
  without.run(3000);
  EXPECT_GT(std::abs(with.world().particles.angular_velocity[0] -
                     without.world().particles.angular_velocity[0]),
            1e-3 * 30.0);
}

// Whether every disk was turned round by its wall (LAMMPS' run): it moves up.
void turned_round(LammpsInstance& l, std::size_t disks) {
  for (std::size_t k = 1; k <= disks; ++k)
    EXPECT_GT(l.velocity(static_cast<int>(k))[1], 0.0) << "disk " << k;
}

// Disks against segment walls in both engines, given as the fix's line and as the same walls
// (and drivers) built natively, with each tangential law for 5000 steps of 1e-7 s: rounding as
// above, and `reached` says whether the disks met their walls.
void segment_walls_agree(
    const char* what, const std::vector<Disk>& disks, const std::string& fix,
    const std::function<void(World&)>& walls,
    const std::function<void(LammpsInstance&, std::size_t)>& reached = turned_round,
    const Material& m = grains()) {
  const double dt = 1e-7;
  const int steps = 5000;
  for (const std::string tangential : {"coulomb", "cundall_strack", "mindlin"}) {
    SCOPED_TRACE(tangential);
    LammpsInstance l;
    set_up(l, "hertz " + tangential, m, disks, newton_allowed(tangential, m), dt);
    l.commands({fix, "fix move all nve/sphere disc", "fix plane all enforce2d",
                "run " + std::to_string(steps)});
    Simulation s = native("hertz", tangential, m, disks, dt, VerletVelocity::half_step, walls);
    s.run(static_cast<std::uint64_t>(steps));
    const Difference d = between(l, s);
    std::printf("%s, %s: %.2e m, %.2e m/s, %.2e rad/s\n", what, tangential.c_str(), d.position,
                d.velocity, d.spin);
    EXPECT_LT(d.position, 1e-15);
    EXPECT_LT(d.velocity, 1e-12 * 1.0);
    EXPECT_LT(d.spin, 1e-12 * 30.0);
    reached(l, disks.size());
  }
}

// fix granthesis/wall against the native segment walls: a spinning disk thrown obliquely onto a
// floor, and one falling onto the joint of a V (the shared end point touched once), through the
// whole contact.
TEST(VerletAgreement, SegmentWallsAgreeToRounding) {
  // 50 um above the floor, and 0.18 mm above the V's faces, with 0.2 and 1 m/s to go
  const std::vector<Disk> disks{{{-0.02, 0.00505}, {0.2, -0.2}, 0.005, 2.0e-4, 30.0},
                                {{0.04, 0.0032}, {0.0, -1.0}, 0.004, 1.5e-4, -10.0}};
  // the floor up to x = 0.03, then a V whose joint lies under the second disk
  segment_walls_agree("walls", disks,
                      "fix walls all granthesis/wall segment -0.05 0 0.03 0 type 1 segment 0.03 0 "
                      "0.04 -0.001 type 1 segment 0.04 -0.001 0.05 0.002 type 1",
                      [](World& w) {
                        w.add_wall({-0.05, 0.0}, {0.03, 0.0});
                        w.add_wall({0.03, 0.0}, {0.04, -0.001});
                        w.add_wall({0.04, -0.001}, {0.05, 0.002});
                      });
}

// The three motions of fix granthesis/wall against the native drivers of segments: a vibrating
// floor, one moving up and one turning, each met by a falling disk of material m: the walls are
// where the drivers put them at every step.
void moving_segments_agree(const char* what, const Material& m) {
  // 50 um above each segment, falling at 0.3 m/s
  const std::vector<Disk> disks{{{-0.02, 0.00505}, {0.05, -0.3}, 0.005, 2.0e-4, 30.0},
                                {{0.075, 0.00505}, {0.0, -0.3}, 0.005, 2.0e-4, 0.0},
                                {{0.14, 0.00405}, {-0.02, -0.3}, 0.004, 1.5e-4, -10.0}};
  segment_walls_agree(
      what, disks,
      "fix walls all granthesis/wall segment -0.05 0 0.03 0 type 1 vibrate 0 1 2e-4 40 0 segment "
      "0.06 0 0.09 0 type 1 velocity 0 0.1 segment 0.11 0 0.15 0 type 1 rotate 0.13 0 2",
      [](World& w) {
        const auto moved = [&](Vec2 a, Vec2 b, Motion motion) {
          Driver d;
          d.motion = motion;
          d.targets.segments = {static_cast<std::uint32_t>(w.add_wall(a, b))};
          w.drivers.push_back(d);
        };
        moved({-0.05, 0.0}, {0.03, 0.0}, Vibrate{{0.0, 1.0}, 2e-4, 40.0, 0.0});
        moved({0.06, 0.0}, {0.09, 0.0}, Translate{{0.0, 0.1}});
        moved({0.11, 0.0}, {0.15, 0.0}, Rotate{{0.13, 0.0}, 2.0});
      },
      turned_round, m);
}

TEST(VerletAgreement, MovingSegmentsAgreeToRounding) {
  moving_segments_agree("moving walls", grains());
}

// The same with rolling resistance against the walls (the turning wall's spin in the relative
// spin).
TEST(VerletAgreement, RollingOnMovingSegmentsAgreesToRounding) {
  Material m = grains();
  m.rolling_friction = 0.3;
  moving_segments_agree("rolling on moving walls", m);
}

// A segment sweeping at 4 m/s onto a disk at rest from 1.5 mm away, farther than the 1 mm skin:
// fix granthesis/wall's rows of near segments (built for the disk without this one) must be
// built again as the segment comes near, though no atom moves and LAMMPS keeps its lists.
TEST(VerletAgreement, ASegmentSweepingFromBeyondTheSkinIsMet) {
  const std::vector<Disk> disks{{{-0.01, 0.0}, {0.0, 0.0}, 0.005, 2.0e-4, 0.0}};
  segment_walls_agree(
      "sweeping wall", disks,
      "fix walls all granthesis/wall segment -0.0165 -0.01 -0.0165 0.01 type 1 velocity 4 0",
      [](World& w) {
        Driver d;
        d.motion = Translate{{4.0, 0.0}};
        d.targets.segments = {
            static_cast<std::uint32_t>(w.add_wall({-0.0165, -0.01}, {-0.0165, 0.01}))};
        w.drivers.push_back(d);
      },
      [](LammpsInstance& l, std::size_t) { EXPECT_GT(l.velocity(1)[0], 1.0); });
}

} // namespace
} // namespace talus::lammps_test
