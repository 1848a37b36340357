#include "io/lammps_export.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <optional>
#include <variant>

#include <fmt/format.h>

#include "drivers/drivers.hpp"
#include "io/checkpoint.hpp"
#include "io/lammps_stages.hpp"
#include "io/lammps_words.hpp"
#include "scenario/file/load.hpp"
#include "simulation/rolling_pass.hpp"
#include "talus/error.hpp"
#include "talus/material_keys.hpp"

namespace talus {

namespace {

std::string refused(const std::string& key, const std::string& why) {
  return "key '" + key + "': " + why + "; talus export lammps writes only what LAMMPS and the " +
         "talus package express exactly";
}

// What LAMMPS cannot express: the reason, with the key to change, or nothing.
std::optional<std::string> refusal(const Scenario& s) {
  if (s.simulation.lever_arm != LeverArm::contact_point)
    return refused("simulation.lever_arm",
                   "the lever arms '" + std::string(to_string(s.simulation.lever_arm)) +
                       "' are a convention of LAMMPS' own granular styles; pair_style granthesis "
                       "takes them to the contact point; allowed: contact_point "
                       "(validation/crosscheck.py puts gran/hooke or granular in the deck to "
                       "compare with them)");
  if (s.simulation.linear_damping != LinearDamping::never_attractive)
    return refused("simulation.linear_damping",
                   "pair_style granthesis derives the linear dashpot as never_attractive; allowed: "
                   "never_attractive");
  for (const Material& m : s.materials)
    if (m.rigid)
      return refused("materials", "material '" + m.name +
                                      "' is rigid, which pair_coeff does not express yet; allowed: "
                                      "rigid = false");
  for (const DriverSection& d : s.drivers) {
    if (d.type == "servo")
      return refused("drivers", "a servo driver has no counterpart in fix granthesis/wall; "
                                "allowed types: vibrate, translate, rotate (docs/lammps.md names "
                                "LAMMPS' own ways to hold a wall at a load)");
    if (d.type == "cell" && d.pressure > 0.0)
      return refused("drivers", "a cell held at a pressure has no counterpart with the same "
                                "controller (fix press/berendsen and fix box/relax differ; "
                                "docs/lammps.md); allowed: a cell at a strain_rate (fix deform)");
  }
  if (s.frost.model == "front")
    return refused("frost.model", "the freezing front has no LAMMPS style; allowed: none, uniform "
                                  "(fix frost/heave)");
  return cell_and_stages_refusal(s);
}

// A LAMMPS atom type per (role, material): role 0 the grains, 1 the fixed wall particles, 2 + k
// those driver k moves, and last the materials of the wall segments (types with no atoms, whose
// pair_coeff gives fix granthesis/wall the segments' material). Types are numbered in that order.
struct Typing {
  std::vector<int> type_of;                 ///< per particle, from 1
  std::vector<std::pair<int, int>> key_of;  ///< per type - 1: (role, material)
  std::vector<std::vector<int>> role_types; ///< per role: its types
  std::vector<int> segment_type;            ///< per wall segment: its material's type
};

int role_of(const BuiltScenario& b, std::size_t i) {
  const Particles& p = b.world.particles;
  if (p.kind[i] == Kind::free) return 0;
  if (p.kind[i] == Kind::fixed) return 1;
  int role = -1;
  for (std::size_t k = 0; k < b.world.drivers.size(); ++k) {
    const auto& t = b.world.drivers[k].targets.particles;
    if (std::find(t.begin(), t.end(), static_cast<std::uint32_t>(i)) == t.end()) continue;
    if (role >= 0)
      throw InvalidArgument(refused("drivers", "wall particle " + std::to_string(i) +
                                                   " is moved by two drivers; fix move takes "
                                                   "one motion per atom"));
    role = 2 + static_cast<int>(k);
  }
  if (role < 0)
    throw InvalidArgument(
        refused("drivers", "particle " + std::to_string(i) + " is held but no driver moves it"));
  return role;
}

Typing assign_types(const BuiltScenario& b) {
  const Particles& p = b.world.particles;
  std::vector<int> roles(p.size());
  std::map<std::pair<int, int>, int> types;
  for (std::size_t i = 0; i < p.size(); ++i) {
    roles[i] = role_of(b, i);
    types.emplace(std::pair{roles[i], static_cast<int>(p.material[i])}, 0);
  }
  const int segment_role = 2 + static_cast<int>(b.world.drivers.size());
  for (const Segment& w : b.world.walls)
    types.emplace(std::pair{segment_role, static_cast<int>(w.material)}, 0);
  Typing t;
  t.role_types.resize(3 + b.world.drivers.size());
  for (auto& [key, type] : types) {
    t.key_of.push_back(key);
    type = static_cast<int>(t.key_of.size());
    t.role_types[static_cast<std::size_t>(key.first)].push_back(type);
  }
  for (std::size_t i = 0; i < p.size(); ++i)
    t.type_of.push_back(types.at({roles[i], static_cast<int>(p.material[i])}));
  for (const Segment& w : b.world.walls)
    t.segment_type.push_back(types.at({segment_role, static_cast<int>(w.material)}));
  return t;
}

// The box: a periodic direction's period as it is; otherwise the native engine's escape box (the
// container and as much again around it), or the extent of the particles and wall segments and
// as much again around it (at least ten radii).
struct Box {
  Vec2 lo, hi;
  double z = 0.0;
  bool periodic_x = false, periodic_y = false;
};

Box lammps_box(const BuiltScenario& b) {
  const Particles& p = b.world.particles;
  Box box;
  box.z = p.max_radius();
  Vec2 lo{HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL};
  for (std::size_t i = 0; i < p.size(); ++i) {
    lo = {std::min(lo.x, p.position[i].x - p.radius[i]),
          std::min(lo.y, p.position[i].y - p.radius[i])};
    hi = {std::max(hi.x, p.position[i].x + p.radius[i]),
          std::max(hi.y, p.position[i].y + p.radius[i])};
  }
  // the wall segments too: grains that roll along one stay inside the box
  for (const Segment& w : b.world.walls)
    for (const Vec2 e : {w.a, w.b}) {
      lo = {std::min(lo.x, e.x), std::min(lo.y, e.y)};
      hi = {std::max(hi.x, e.x), std::max(hi.y, e.y)};
    }
  if (b.config.escape_hi.x > b.config.escape_lo.x) {
    lo = {std::min(lo.x, b.config.escape_lo.x), std::min(lo.y, b.config.escape_lo.y)};
    hi = {std::max(hi.x, b.config.escape_hi.x), std::max(hi.y, b.config.escape_hi.y)};
  } else {
    const Vec2 margin{std::max(hi.x - lo.x, 10.0 * box.z), std::max(hi.y - lo.y, 10.0 * box.z)};
    lo -= margin;
    hi += margin;
  }
  box.lo = lo;
  box.hi = hi;
  const Domain& d = b.world.domain;
  if ((box.periodic_x = d.periodic_x)) box.lo.x = d.lo.x, box.hi.x = d.hi.x;
  if ((box.periodic_y = d.periodic_y)) box.lo.y = d.lo.y, box.hi.y = d.hi.y;
  return box;
}

// The particles as the native engine starts a run with them: its drivers give the walls they
// move their velocity at t = 0 (Simulation's constructor). LAMMPS' fix move sets a velocity only
// from the first step on, so the data file must carry it, or the first forces, computed in the
// run's setup, see still walls beside the native engine's moving ones.
Particles started(const World& w) {
  World moved = w;
  for (Driver d : w.drivers) {
    attach(d, moved);
    apply(d, 0.0, moved.particles, moved.walls);
  }
  return moved.particles;
}

std::string data_file(const Scenario& s, const BuiltScenario& b, const Typing& t, const Box& box) {
  const Particles p = started(b.world);
  std::string out = fmt::format("LAMMPS data file: {}, written by talus export lammps\n\n", s.name);
  out += fmt::format("{} atoms\n{} atom types\n\n", p.size(), t.key_of.size());
  out +=
      fmt::format("{} {} xlo xhi\n{} {} ylo yhi\n{} {} zlo zhi\n", exact(box.lo.x), exact(box.hi.x),
                  exact(box.lo.y), exact(box.hi.y), exact(-box.z), exact(box.z));
  // a sheared cell's box is LAMMPS' tilted one, untilted at the start
  out += shears_in_any_stage(s) ? "0 0 0 xy xz yz\n\n" : "\n";
  // read_data takes a density and makes the mass 4/3 pi r^3 rho; masses.NAME then sets the
  // native engine's masses exactly
  out += "Atoms # sphere\n\n";
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = p.radius[i];
    const double density = p.mass[i] / (4.0 / 3.0 * std::numbers::pi * r * r * r);
    out += fmt::format("{} {} {} {} {} {} 0\n", i + 1, t.type_of[i], exact(2.0 * r), exact(density),
                       exact(p.position[i].x), exact(p.position[i].y));
  }
  out += "\nVelocities\n\n";
  for (std::size_t i = 0; i < p.size(); ++i)
    out += fmt::format("{} {} {} 0 0 0 {}\n", i + 1, exact(p.velocity[i].x), exact(p.velocity[i].y),
                       exact(p.angular_velocity[i]));
  return out;
}

std::string masses_file(const BuiltScenario& b) {
  const Particles& p = b.world.particles;
  std::string out = "# the native engine's masses, exactly (read_data gives 4/3 pi r^3 rho)\n";
  for (std::size_t i = 0; i < p.size(); ++i)
    out += fmt::format("set atom {} mass {}\n", i + 1, exact(p.mass[i]));
  return out;
}

std::string type_list(const std::vector<int>& types) {
  std::string out;
  for (const int t : types) out.append(out.empty() ? "" : " ").append(std::to_string(t));
  return out;
}

// fix move for driver k's group: wiggle, linear or rotate, as the native motion is.
std::string driver_fix(const Driver& d, std::size_t k) {
  const std::string id = fmt::format("drive{}", k + 1);
  if (const auto* v = std::get_if<Vibrate>(&d.motion)) {
    const Vec2 a = v->amplitude / norm(v->direction) * v->direction;
    if (v->phase == 0.0)
      return fmt::format("fix {0} {0} move wiggle {1} {2} 0 {3}\n", id, exact(a.x), exact(a.y),
                         exact(1.0 / v->frequency));
    // a phase: the displacement A sin(w t + phase) and its rate as variables of the time
    const double w = 2.0 * std::numbers::pi * v->frequency;
    std::string out;
    for (const auto& [axis, amp] : {std::pair{"x", a.x}, {"y", a.y}}) {
      out += fmt::format("variable {}_d{} equal {}*sin({}*time+{})\n", id, axis, exact(amp),
                         exact(w), exact(v->phase));
      out += fmt::format("variable {}_v{} equal {}*cos({}*time+{})\n", id, axis, exact(amp * w),
                         exact(w), exact(v->phase));
    }
    return out + fmt::format("fix {0} {0} move variable v_{0}_dx v_{0}_dy NULL v_{0}_vx v_{0}_vy "
                             "NULL\n",
                             id);
  }
  if (const auto* t = std::get_if<Translate>(&d.motion))
    return fmt::format("fix {0} {0} move linear {1} {2} 0\n", id, exact(t->velocity.x),
                       exact(t->velocity.y));
  const auto& r = std::get<Rotate>(d.motion);
  if (r.angular_velocity == 0.0) return "# " + id + ": a rotation at rate 0: the walls stay\n";
  return fmt::format("fix {0} {0} move rotate {1} {2} 0 0 0 {3} {4}\n", id, exact(r.centre.x),
                     exact(r.centre.y), r.angular_velocity > 0.0 ? 1 : -1,
                     exact(2.0 * std::numbers::pi / std::abs(r.angular_velocity)));
}

std::string deck_header(const Scenario& s, const BuiltScenario& b, const std::string& command) {
  std::string out = fmt::format("# {}: {}\n", s.name, s.description);
  out += "# Written by: " + command + "\n";
  if (s.stages.size() < 2)
    out +=
        fmt::format("# Run it here: talus-lmp -in in.{0} (or mpirun -np N talus-lmp -in in.{0}); "
                    "-var steps K\n# runs K steps instead of the whole {1} s, -var "
                    "snapshot_every K dumps every K steps.\n",
                    s.name, exact(s.simulation.duration));
  else
    out +=
        fmt::format("# Run it here: talus-lmp -in in.{0} (or mpirun -np N talus-lmp -in in.{0}): "
                    "its {1} stages,\n# {2} s, one LAMMPS run each; -var snapshot_every K dumps "
                    "every K steps.\n",
                    s.name, s.stages.size(), exact(s.simulation.duration));
  out += fmt::format(
      "# The native scenario's system: its grains after the packing, materials, laws, timestep,\n"
      "# gravity, wall particles, wall segments and drivers. LAMMPS' atom ids are the native\n"
      "# ids + 1. LAMMPS integrates with velocity Verlet (the scenario: {}); compute\n"
      "# erotate/sphere counts 2/5 m r^2 for every atom ({}).\n",
      to_string(b.config.integrator),
      s.particles.shape == Shape::disk ? "the native grains are disks, of 1/2 m r^2"
                                       : "the native grains are spheres too");
  if (b.config.integrator == Integrator::verlet)
    out +=
        b.config.verlet_velocity == VerletVelocity::half_step
            ? "# The scenario's Verlet gives the dampers the half-step velocity, as LAMMPS does:\n"
              "# the two engines agree to rounding until chaos parts them.\n"
            : "# The scenario's Verlet gives the dampers the predicted velocity; with\n"
              "# simulation.verlet_velocity = half_step it gives LAMMPS' half-step one.\n";
  return out;
}

std::string pair_section(const Scenario& s, const BuiltScenario& b, const Typing& t) {
  // a Hertz damping left to be derived is derived by LAMMPS as natively, per contact
  // rolling resistance's damping takes the grains' inertia, which the pair style must be told
  const bool rolling = has_rolling_resistance(b.world);
  std::string out =
      fmt::format("pair_style granthesis {} {}{}{}\n", name_of(s.simulation.normal_law),
                  name_of(s.simulation.tangential_law),
                  with_normal_law(s.simulation.normal_law,
                                  []<class N>() { return N::damping_needs_impact_speed; })
                      ? fmt::format(" impact_speed {}", s.simulation.impact_speed)
                      : std::string(),
                  !rolling                           ? ""
                  : s.particles.shape == Shape::disk ? " inertia disc"
                                                     : " inertia sphere");
  for (std::size_t k = 0; k < t.key_of.size(); ++k)
    out += fmt::format(
        "pair_coeff {0} {0} {1}\n", k + 1,
        pair_coefficient_words(b.world.materials[static_cast<std::size_t>(t.key_of[k].second)]));
  return out;
}

// The uniform frost rule: the native engine tests the kinetic energy at its thermo output,
// against kinetic_threshold x sum(m g R) of the grains, and heaves above the container's floor.
std::string frost_section(const Scenario& s, const BuiltScenario& b, std::uint64_t thermo) {
  if (s.frost.model != "uniform") return "";
  const Particles& p = b.world.particles;
  double scale = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i)) scale += p.mass[i] * norm(b.world.gravity) * p.radius[i];
  std::string out = fmt::format(
      "fix frost grains frost/heave epsilon {} factor {} table {} interval {} every {} "
      "initial_wait yes inertia {}\n",
      exact(s.frost.kinetic_threshold * scale), exact(s.frost.heave_factor), exact(b.bounds.lo.y),
      exact(s.frost.min_interval), thermo, s.particles.shape == Shape::disk ? "disc" : "sphere");
  if (s.frost.cycles > 0)
    out += fmt::format("variable heaves equal f_frost\nfix cycles grains halt {} v_heaves >= {} "
                       "error continue\n",
                       thermo, s.frost.cycles);
  return out;
}

// The segment a driver moves: its motion as fix granthesis/wall words ("" when none moves it).
std::string segment_motion(const BuiltScenario& b, std::size_t s) {
  for (const Driver& d : b.world.drivers) {
    const auto& t = d.targets.segments;
    if (std::find(t.begin(), t.end(), static_cast<std::uint32_t>(s)) == t.end()) continue;
    if (const auto* v = std::get_if<Translate>(&d.motion))
      return fmt::format(" velocity {} {}", exact(v->velocity.x), exact(v->velocity.y));
    if (const auto* r = std::get_if<Rotate>(&d.motion))
      return fmt::format(" rotate {} {} {}", exact(r->centre.x), exact(r->centre.y),
                         exact(r->angular_velocity));
    const auto& v = std::get<Vibrate>(d.motion);
    return fmt::format(" vibrate {} {} {} {} {}", exact(v.direction.x), exact(v.direction.y),
                       exact(v.amplitude), exact(v.frequency), exact(v.phase));
  }
  return "";
}

// The wall segments as fix granthesis/wall, with the same laws and the segments' materials; their
// elastic energy joins pe. One segment a line.
std::string walls_section(const BuiltScenario& b, const Typing& t) {
  if (b.world.walls.empty()) return "";
  std::string out = "fix walls grains granthesis/wall";
  for (std::size_t s = 0; s < b.world.walls.size(); ++s) {
    const Segment& w = b.world.walls[s];
    out += fmt::format(" &\n  segment {} {} {} {} type {}{}", exact(w.a.x), exact(w.a.y),
                       exact(w.b.x), exact(w.b.y), t.segment_type[s], segment_motion(b, s));
  }
  return out + "\nfix_modify walls energy yes\n";
}

std::string motion_section(const Scenario& s, const BuiltScenario& b, const Typing& t) {
  std::string out = fmt::format("group grains type {}\n", type_list(t.role_types[0]));
  if (!t.role_types[1].empty())
    out += fmt::format("group fixed_walls type {}\n", type_list(t.role_types[1]));
  for (std::size_t k = 0; k < b.world.drivers.size(); ++k)
    if (!t.role_types[2 + k].empty())
      out += fmt::format("group drive{} type {}\n", k + 1, type_list(t.role_types[2 + k]));
  out += fmt::format("fix integrate grains nve/sphere{}\n",
                     s.particles.shape == Shape::disk ? " disc" : "");
  if (const double g = norm(b.world.gravity); g > 0.0)
    out += fmt::format("fix gravity grains gravity {} vector {} {} 0\n", exact(g),
                       exact(b.world.gravity.x / g), exact(b.world.gravity.y / g));
  for (std::size_t k = 0; k < b.world.drivers.size(); ++k)
    if (!t.role_types[2 + k].empty()) out += driver_fix(b.world.drivers[k], k);
  out += walls_section(b, t);
  return out + "fix plane all enforce2d\n";
}

std::string deck(const Scenario& s, const BuiltScenario& b, const Typing& t, const Box& box,
                 const std::string& command) {
  const double dt = b.config.timestep;
  const std::uint64_t thermo = steps_of(s.output.thermo_interval, dt);
  std::string out = deck_header(s, b, command) + "\n";
  out += fmt::format("variable steps index {}\n", steps_of(s.simulation.duration, dt));
  if (s.output.snapshot_interval > 0.0)
    out +=
        fmt::format("variable snapshot_every index {}\n", steps_of(s.output.snapshot_interval, dt));
  out += "\n";
  out += fmt::format("units si\ndimension 2\natom_style sphere\natom_modify map array\n"
                     "boundary {} {} p\ncomm_modify vel yes\n",
                     box.periodic_x ? "p" : "f", box.periodic_y ? "p" : "f");
  // a law with a spring: each rank computes its own atoms' contacts (pair_style granthesis)
  if (keeps_history(s.simulation.tangential_law) || has_rolling_resistance(b.world))
    out += "newton off\n";
  out += fmt::format("read_data data.{0}\ninclude masses.{0}\n\n", s.name);
  out += pair_section(s, b, t) + "\n" + motion_section(s, b, t);
  out += frost_section(s, b, thermo) + "\n";
  out += fmt::format("neighbor {} bin\nneigh_modify delay 0 every 1 check yes\ntimestep {}\n\n",
                     exact(b.world.particles.min_radius()), exact(dt));
  // the coordination number as the native engine counts it: contacts per grain, with walls.
  // contact/atom counts a grain's contacts only with atoms in its own group, so it runs on all
  // atoms and the average is over the grains; it does not see the wall segments, whose fix
  // counts its own.
  out += "compute grains_ke grains ke\ncompute grains_rotation grains erotate/sphere\n"
         "compute contacts all contact/atom\n";
  // (a per-atom reduce: in a variable f_walls would be the fix's global scalar)
  out += b.world.walls.empty() ? "compute coordination grains reduce ave c_contacts\n"
                               : "compute contact_parts grains reduce ave c_contacts f_walls\n"
                                 "variable coordination equal "
                                 "c_contact_parts[1]+c_contact_parts[2]\n";
  // a cell's stress, its contact part as thermo.csv's stress_xx, stress_yy and stress_yx
  // (compression positive: LAMMPS' pressure tensor, sum d_a f_b / A with d from j to i)
  const bool cell = std::ranges::any_of(
      b.world.drivers, [](const Driver& d) { return std::holds_alternative<Cell>(d.motion); });
  if (cell) out += "compute contact_stress all pressure NULL virial\n";
  // f_gravity: the grains' potential energy in gravity; f_walls[1]: the walls' work on them
  out += fmt::format(
      "thermo_style custom step time c_grains_ke c_grains_rotation {}coordination "
      "pe press{}{}{}{}\n",
      b.world.walls.empty() ? "c_" : "v_", norm(b.world.gravity) > 0.0 ? " f_gravity" : "",
      b.world.walls.empty() ? "" : " f_walls[1]", s.frost.model == "uniform" ? " f_frost" : "",
      cell ? " c_contact_stress[1] c_contact_stress[2] c_contact_stress[4] vol" : "");
  out += fmt::format("thermo {}\nthermo_modify norm no\n", thermo);
  if (s.output.snapshot_interval > 0.0)
    out += fmt::format("dump snapshots all custom ${{snapshot_every}} dump.{}.lammpstrj id type "
                       "radius mass x y vx vy omegaz\ndump_modify snapshots sort id format float "
                       "%.17g\n",
                       s.name);
  return out + "\n" +
         cell_and_runs(s, b.world.domain.periodic_x, b.world.domain.periodic_y, dt,
                       steps_of(s.simulation.duration, dt));
}

} // namespace

void check_lammps_export(const Scenario& s) {
  if (const auto why = refusal(s)) throw InvalidArgument(*why);
}

LammpsCase export_lammps(const Scenario& s, const BuiltScenario& built,
                         const std::string& command) {
  check_lammps_export(s);
  const Typing t = assign_types(built);
  const Box box = lammps_box(built);
  return {.name = s.name,
          .deck = deck(s, built, t, box, command),
          .data = data_file(s, built, t, box),
          .masses = masses_file(built),
          .scenario = to_toml(s)};
}

void write_lammps_case(const LammpsCase& c, const std::string& dir) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path d(dir);
  write_file_atomically((d / ("data." + c.name)).string(), c.data);
  write_file_atomically((d / ("masses." + c.name)).string(), c.masses);
  write_file_atomically((d / "scenario.toml").string(), c.scenario);
  write_file_atomically((d / ("in." + c.name)).string(), c.deck);
}

} // namespace talus
