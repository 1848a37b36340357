#pragma once
// Two disks in the host (LAMMPS, or LIGGGHTS with TALUS_HOST_LIGGGHTS) and in the native engine:
// what the pair style's tests against the native engine and the closed forms share.
#include <cmath>
#include <functional>
#include <initializer_list>
#include <numbers>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "lammps_instance.hpp"
#include "simulation/simulation.hpp"
#include "talus/material_keys.hpp"

namespace talus::lammps_test {

// The velocities of ghost atoms, which the pair style needs, in each host's words.
#ifdef TALUS_HOST_LIGGGHTS
inline const std::string ghost_velocities = "communicate single vel yes";
// LIGGGHTS' nve/sphere has no disc option: the head-on collisions below do not turn the disks
inline const std::string integrate = "fix move all nve/sphere";
#else
inline const std::string ghost_velocities = "comm_modify vel yes";
inline const std::string integrate = "fix move all nve/sphere disc";
#endif

struct Disk {
  Vec2 position, velocity;
  double radius, mass, spin;
};

// Words joined by spaces (built by append: GCC 12 warns falsely on some chains of +).
inline std::string words(std::initializer_list<std::string> parts) {
  std::string out;
  for (const std::string& p : parts) out.append(out.empty() ? "" : " ").append(p);
  return out;
}

// Two disks in the host (2d, SI units), their forces computed once by `run 0`.
inline void set_up(LammpsInstance& l, const std::string& laws, const Material& m,
                   const std::vector<Disk>& disks, bool newton, double dt) {
  l.commands({"dimension 2", "units si", "atom_style sphere", "atom_modify map array",
              "boundary f f p", ghost_velocities, newton ? "newton on" : "newton off",
              "region box block -1 1 -1 1 -0.01 0.01", "create_box 1 box"});
  for (std::size_t k = 0; k < disks.size(); ++k) {
    const Disk& d = disks[k];
    const std::string id = std::to_string(k + 1);
    l.command(words({"create_atoms 1 single", exact(d.position.x), exact(d.position.y), "0"}));
    l.command(words({"set atom", id, "diameter", exact(2.0 * d.radius)}));
    l.command(words({"set atom", id, "mass", exact(d.mass)}));
    l.command(words({"set atom", id, "vx", exact(d.velocity.x), "vy", exact(d.velocity.y)}));
    // the spin directly: LIGGGHTS' set has no omega
    l.lmp()->atom->omega[l.index(static_cast<int>(k) + 1)][2] = d.spin;
  }
  l.commands({words({"pair_style granthesis", laws}), "pair_coeff 1 1 " + pair_coefficient_words(m),
              "neighbor 0.001 bin", words({"timestep", exact(dt)})});
}

// The same disks in the native engine: the forces its first force stage computes.
inline Simulation native(
    const std::string& normal, const std::string& tangential, const Material& m,
    const std::vector<Disk>& disks, double dt, VerletVelocity velocity = VerletVelocity::predicted,
    const std::function<void(World&)>& more = [](World&) {}) {
  World w;
  w.materials = {m};
  for (const Disk& d : disks)
    w.add_particle({.position = d.position,
                    .radius = d.radius,
                    .velocity = d.velocity,
                    .angular_velocity = d.spin,
                    .mass = d.mass});
  more(w);
  SimulationConfig c;
  c.timestep = dt;
  c.integrator = Integrator::verlet;
  c.verlet_velocity = velocity;
  c.normal_law = parse_normal_law(normal);
  c.tangential_law = parse_tangential_law(tangential);
  return Simulation(std::move(w), c);
}

inline Material grains() {
  Material m; // every key at its default
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
inline std::vector<Disk> random_pair(RandomStream& rng) {
  const double ri = rng.uniform(0.004, 0.006), rj = rng.uniform(0.003, 0.007);
  const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const double dist = ri + rj - rng.uniform(1e-6, 0.1 * std::min(ri, rj));
  const Vec2 n{std::cos(angle), std::sin(angle)};
  const auto speed = [&] { return Vec2{rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)}; };
  return {{{0.01, -0.02}, speed(), ri, rng.uniform(1e-4, 3e-4), rng.uniform(-50.0, 50.0)},
          {Vec2{0.01, -0.02} - dist * n, speed(), rj, rng.uniform(1e-4, 3e-4),
           rng.uniform(-50.0, 50.0)}};
}

// A head-on collision of two equal disks in the host, stepped by fix nve/sphere: the restitution
// and the contact's duration, and the total momentum before and after.
struct Collision {
  double restitution, duration, momentum_before, momentum_after;
};

inline Collision collide(const std::string& laws, const Material& m, double radius, double mass,
                         double speed, double dt) {
  LammpsInstance l;
  const double gap = 1e-7; // a few steps before the touch
  const std::vector<Disk> disks{{{-radius - gap, 0.0}, {speed, 0.0}, radius, mass, 0.0},
                                {{radius + gap, 0.0}, {-speed, 0.0}, radius, mass, 0.0}};
  set_up(l, laws, m, disks, true, dt);
  l.commands({integrate, "fix plane all enforce2d", "run 0"});
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

} // namespace talus::lammps_test
