// pair_style granthesis in LAMMPS against the native engine and the closed forms: single contacts
// to the bit, two-disk collisions for both normal laws, and the errors of bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "lammps_instance.hpp"
#include "physics/reference_values.hpp"
#include "simulation/simulation.hpp"
#include "talus/closed_forms.hpp"
#include "talus/material_keys.hpp"

namespace talus::lammps_test {
namespace {

struct Disk {
  Vec2 position, velocity;
  double radius, mass, spin;
};

// Words joined by spaces (built by append: GCC 12 warns falsely on some chains of +).
std::string words(std::initializer_list<std::string> parts) {
  std::string out;
  for (const std::string& p : parts) out.append(out.empty() ? "" : " ").append(p);
  return out;
}

// Two disks in LAMMPS (2d, SI units), their forces computed once by `run 0`.
void set_up(LammpsInstance& l, const std::string& laws, const Material& m,
            const std::vector<Disk>& disks, bool newton, double dt) {
  l.commands({"dimension 2", "units si", "atom_style sphere", "atom_modify map array",
              "boundary f f p", "comm_modify vel yes", newton ? "newton on" : "newton off",
              "region box block -1 1 -1 1 -0.01 0.01", "create_box 1 box"});
  for (std::size_t k = 0; k < disks.size(); ++k) {
    const Disk& d = disks[k];
    const std::string id = std::to_string(k + 1);
    l.command(words({"create_atoms 1 single", exact(d.position.x), exact(d.position.y), "0"}));
    l.command(words({"set atom", id, "diameter", exact(2.0 * d.radius)}));
    l.command(words({"set atom", id, "mass", exact(d.mass)}));
    l.command(words({"set atom", id, "vx", exact(d.velocity.x), "vy", exact(d.velocity.y)}));
    l.command(words({"set atom", id, "omega 0 0", exact(d.spin)}));
  }
  l.commands({words({"pair_style granthesis", laws}), "pair_coeff 1 1 " + pair_coefficient_words(m),
              "neighbor 0.001 bin", words({"timestep", exact(dt)})});
}

// The same disks in the native engine: the forces its first force stage computes.
Simulation native(const std::string& normal, const std::string& tangential, const Material& m,
                  const std::vector<Disk>& disks, double dt) {
  World w;
  w.materials = {m};
  for (const Disk& d : disks)
    w.add_particle({.position = d.position,
                    .radius = d.radius,
                    .velocity = d.velocity,
                    .angular_velocity = d.spin,
                    .mass = d.mass});
  SimulationConfig c;
  c.timestep = dt;
  c.integrator = Integrator::verlet;
  c.normal_law = parse_normal_law(normal);
  c.tangential_law = parse_tangential_law(tangential);
  return Simulation(std::move(w), c);
}

Material grains() {
  Material m = default_material();
  m.young = 5.0e7;
  m.normal_stiffness = 2.0e5;
  m.normal_damping_rate = 40.0;
  m.hertz_damping = 2.0e-5;
  m.friction = 0.4;
  m.tangential_damping = 300.0;
  return m;
}

// Random touching pairs: overlaps up to a tenth of the smaller radius, any approach, slip and spin,
// so that some contacts stick (viscous force below mu F_n) and some slide.
std::vector<Disk> random_pair(RandomStream& rng) {
  const double ri = rng.uniform(0.004, 0.006), rj = rng.uniform(0.003, 0.007);
  const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const double dist = ri + rj - rng.uniform(1e-6, 0.1 * std::min(ri, rj));
  const Vec2 n{std::cos(angle), std::sin(angle)};
  const auto speed = [&] { return Vec2{rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)}; };
  return {{{0.01, -0.02}, speed(), ri, rng.uniform(1e-4, 3e-4), rng.uniform(-50.0, 50.0)},
          {Vec2{0.01, -0.02} - dist * n, speed(), rj, rng.uniform(1e-4, 3e-4),
           rng.uniform(-50.0, 50.0)}};
}

// The force and torque LAMMPS applies to each disk are the native engine's, bit for bit: both
// evaluate the laws in src/talus on the same doubles (a pair listed as (j, i) by LAMMPS gives the
// same bits: every operation of the geometry is symmetric, or negated exactly, under the swap).
TEST(PairGranthesis, SingleContactsEqualTheNativeEngineBitForBit) {
  RandomStream rng(2026, 23);
  const double dt = 1e-6;
  for (const char* normal : {"linear", "hertz"})
    for (const char* tangential : {"coulomb", "none"})
      for (const bool newton : {true, false})
        for (int trial = 0; trial < 5; ++trial) {
          SCOPED_TRACE(words({normal, tangential, newton ? "newton on" : "newton off", "trial",
                              std::to_string(trial)}));
          const std::vector<Disk> disks = random_pair(rng);
          const Material m = grains();
          LammpsInstance l;
          set_up(l, words({normal, tangential}), m, disks, newton, dt);
          l.command("run 0");
          const Simulation s = native(normal, tangential, m, disks, dt);
          const Particles& p = s.world().particles;
          for (int k = 0; k < 2; ++k) {
            EXPECT_EQ(l.force(k + 1)[0], p.force[static_cast<std::size_t>(k)].x);
            EXPECT_EQ(l.force(k + 1)[1], p.force[static_cast<std::size_t>(k)].y);
            EXPECT_EQ(l.torque(k + 1)[2], p.torque[static_cast<std::size_t>(k)]);
          }
          EXPECT_NE(l.force(1)[0], 0.0); // they do touch
        }
}

// A head-on collision of two equal disks in LAMMPS, stepped by fix nve/sphere: the restitution and
// the contact's duration, and the total momentum before and after.
struct Collision {
  double restitution, duration, momentum_before, momentum_after;
};

Collision collide(const std::string& laws, const Material& m, double radius, double mass,
                  double speed, double dt) {
  LammpsInstance l;
  const double gap = 1e-7; // a few steps before the touch
  const std::vector<Disk> disks{{{-radius - gap, 0.0}, {speed, 0.0}, radius, mass, 0.0},
                                {{radius + gap, 0.0}, {-speed, 0.0}, radius, mass, 0.0}};
  set_up(l, laws, m, disks, true, dt);
  l.commands({"fix move all nve/sphere disc", "fix plane all enforce2d", "run 0"});
  const auto momentum = [&] { return mass * (l.velocity(1)[0] + l.velocity(2)[0]); };
  const auto touching = [&] { return l.position(2)[0] - l.position(1)[0] < 2.0 * radius; };
  Collision c{};
  c.momentum_before = momentum();
  long steps = 0, first = -1, last = -1;
  while (steps < 1'000'000 && (first < 0 || touching())) {
    l.command("run 1 pre no post no");
    ++steps;
    if (touching()) {
      if (first < 0) first = steps;
      last = steps;
    }
  }
  c.duration = static_cast<double>(last - first + 1) * dt;
  c.restitution = (l.velocity(2)[0] - l.velocity(1)[0]) / (2.0 * speed);
  c.momentum_after = momentum();
  return c;
}

// The linear law's restitution and duration are the never-attractive closed forms (Schwager &
// Poeschel 2007), within reference::linear_tolerance; resolving the contact with 2000 steps leaves
// the counted duration one step (5e-4 of it) from the exact one. Momentum: rounding only.
TEST(PairGranthesis, LinearCollisionMeetsTheClosedForms) {
  Material m = grains();
  m.normal_damping_rate = 4000.0; // e about 0.87
  const double mass = 2.0e-4, m_eff = 0.5 * mass;
  const double dashpot = m.normal_damping_rate * m_eff;
  const double tc = linear_collision_time(m.normal_stiffness, dashpot, m_eff);
  const Collision c = collide("linear coulomb", m, 0.005, mass, 0.1, tc / 2000.0);
  std::printf("linear: e = %.6f (closed form %.6f), t_c = %.4e s (closed form %.4e s)\n",
              c.restitution, linear_restitution(m.normal_stiffness, dashpot, m_eff), c.duration,
              tc);
  EXPECT_NEAR(c.restitution, linear_restitution(m.normal_stiffness, dashpot, m_eff),
              reference::linear_tolerance * c.restitution);
  EXPECT_NEAR(c.duration, tc, reference::linear_tolerance * tc);
  EXPECT_NEAR(c.momentum_after, c.momentum_before,
              reference::roundoff_tolerance * mass * 0.1 + 1e-20);
}

// The viscoelastic Hertz law's restitution at the impact speed (Brilliantov et al., by accurate
// integration: hertz_restitution) and, for a nearly elastic contact, the elastic duration
// (Landau & Lifshitz), within reference::hertz_tolerance.
TEST(PairGranthesis, HertzCollisionMeetsTheClosedForms) {
  Material m = grains();
  m.hertz_damping = 1.0e-5; // e about 0.85 at this speed
  const double mass = 2.0e-4, m_eff = 0.5 * mass, radius = 0.005, speed = 0.1;
  const double rho = hertz_rho(effective_young(m, m), 0.5 * radius);
  const double tc = hertz_collision_time(m_eff, rho, 2.0 * speed); // at the relative speed
  const Collision c = collide("hertz coulomb", m, radius, mass, speed, tc / 2000.0);
  std::printf("hertz: e = %.6f (closed form %.6f), t_c = %.4e s (elastic %.4e s)\n", c.restitution,
              hertz_restitution(m.hertz_damping, m_eff, rho, 2.0 * speed), c.duration, tc);
  EXPECT_NEAR(c.restitution, hertz_restitution(m.hertz_damping, m_eff, rho, 2.0 * speed),
              reference::hertz_tolerance * c.restitution);
  EXPECT_NEAR(c.duration, tc, 0.05 * tc); // the damping changes the elastic duration a little
  EXPECT_NEAR(c.momentum_after, c.momentum_before,
              reference::roundoff_tolerance * mass * speed + 1e-20);
}

// Two types of disks in a box, then `lines`: an error naming `expected` (run_deck).
void expect_error(const std::vector<std::string>& lines, const std::string& expected) {
  std::vector<std::string> deck{"dimension 2",
                                "units si",
                                "atom_style sphere",
                                "boundary f f p",
                                "comm_modify vel yes",
                                "region box block -1 1 -1 1 -0.01 0.01",
                                "create_box 2 box",
                                "create_atoms 1 single 0 0 0",
                                "create_atoms 2 single 0.009 0 0",
                                "set atom * diameter 0.01",
                                "set atom * density/disc 2650"};
  deck.insert(deck.end(), lines.begin(), lines.end());
  expect_deck_error(deck, expected);
}

TEST(PairGranthesis, BadInputNamesTheSettingAndTheAllowedValues) {
  expect_error({"pair_style granthesis"}, "NORMAL: linear, hertz");
  expect_error({"pair_style granthesis hooke coulomb"}, "unknown normal law 'hooke'");
  expect_error({"pair_style granthesis linear cundall_strack"}, "allowed: coulomb, none");
  expect_error({"pair_style granthesis linear coulomb", "pair_coeff 1 1 stiffness 1e5"},
               "unknown key 'stiffness'; allowed: young, poisson");
  expect_error({"pair_style granthesis linear coulomb", "pair_coeff 1 1 friction -0.1"},
               "friction = -0.1; allowed: >= 0");
  expect_error({"pair_style granthesis linear coulomb", "pair_coeff 1 1 friction nan"},
               "friction = 'nan' is not a finite number");
  expect_error({"pair_style granthesis linear coulomb", "pair_coeff 1 1 young"},
               "young: the value is missing");
  expect_error({"pair_style granthesis linear coulomb", "pair_coeff 1 1 density 2650"},
               "density/disc");
  expect_error({"pair_style granthesis linear coulomb", "pair_coeff 1 1", "run 0"},
               "no pair_coeff for type 2");
  expect_error({"pair_style granthesis hertz coulomb", "pair_coeff * *", "run 0"},
               "needs hertz_damping");
  expect_error(
      {"comm_modify vel no", "pair_style granthesis linear coulomb", "pair_coeff * *", "run 0"},
      "comm_modify vel yes");
}

} // namespace
} // namespace talus::lammps_test
