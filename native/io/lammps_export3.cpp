#include "io/lammps_export3.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "io/lammps_words.hpp"
#include "scenario/file/load3.hpp"
#include "simulation/simulation.hpp"
#include "talus/error.hpp"
#include "talus/material_keys.hpp"

namespace talus {

namespace {

constexpr const char* exactly = "; talus export lammps writes only what LAMMPS and the talus "
                                "package express exactly";

// Type 1: the spheres' material; type 2: the plates' (a type with no atoms, whose pair_coeff
// gives fix granthesis/wall its material), even where the two materials are the same.
constexpr int sphere_type = 1, plate_type = 2;

// A periodic axis' period as it is; otherwise the box and as much again on either side, so that
// a sphere thrown out of an open top stays in LAMMPS' box a while (f boundaries lose atoms).
std::string box_lines(const Scenario3& s) {
  std::string out;
  for (int k = 0; k < 3; ++k) {
    const double lo = component(s.geometry.lo, k), hi = component(s.geometry.hi, k);
    const double margin = s.geometry.periodic[static_cast<std::size_t>(k)] ? 0.0 : hi - lo;
    const char axis = static_cast<char>('x' + k);
    out += fmt::format("{} {} {}lo {}hi\n", exact(lo - margin), exact(hi + margin), axis, axis);
  }
  return out;
}

std::string data_file(const Scenario3& s, const Scene3& scene) {
  const Spheres& p = scene.spheres;
  std::string out = fmt::format("LAMMPS data file: {}, written by talus export lammps\n\n", s.name);
  out += fmt::format("{} atoms\n2 atom types\n\n", p.size());
  out += box_lines(s) + "\n";
  // read_data makes the mass 4/3 pi r^3 rho; masses.NAME then sets the native masses exactly
  return out + sphere_data_sections(p, [](std::size_t) { return sphere_type; });
}

std::string masses_file(const Scene3& scene) {
  const Spheres& p = scene.spheres;
  std::string out = "# the native engine's masses, exactly (read_data gives 4/3 pi r^3 rho)\n";
  for (std::size_t i = 0; i < p.size(); ++i)
    out += fmt::format("set atom {} mass {}\n", i + 1, exact(p.mass[i]));
  return out;
}

std::string deck_header(const Scenario3& s, const BuiltScenario3& b, const std::string& command) {
  std::string out = fmt::format("# {}: {}\n# Written by: {}\n", s.name, s.description, command);
  out += fmt::format(
      "# Run it here: talus-lmp -in in.{0} (or mpirun -np N talus-lmp -in in.{0}); -var steps K\n"
      "# runs K steps instead of the whole {1} s, -var snapshot_every K dumps every K steps.\n"
      "# The native scenario's system: its spheres where the builder put them, materials, laws,\n"
      "# timestep, gravity and the box's plates. LAMMPS' atom ids are the native ids + 1.\n",
      s.name, exact(s.simulation.duration));
  if (b.settings.integrator == Integrator::gear)
    return out + "# The scenario integrates with Gear; LAMMPS with velocity Verlet: the two agree\n"
                 "# to the order of the step, not to rounding.\n";
  out += b.settings.verlet_velocity == VerletVelocity::half_step
             ? "# The scenario's Verlet gives the dampers the half-step velocity, as LAMMPS does:\n"
               "# the two engines agree to rounding until chaos parts them.\n"
             : "# The scenario's Verlet gives the dampers the predicted velocity; with\n"
               "# simulation.verlet_velocity = half_step it gives LAMMPS' half-step one.\n";
  return out;
}

// A driven plate's motion as fix granthesis/wall takes it in 3d, which moves the plate by the
// native lines (talus/plate.hpp) with the time from the fix's definition, the run's start.
std::string motion_words(const PlateDriver& d) {
  const auto v = [](const Vec3& a) {
    return fmt::format("{} {} {}", exact(a.x), exact(a.y), exact(a.z));
  };
  switch (d.motion) {
  case PlateDriver::Motion::vibrate:
    return fmt::format(" vibrate {} {} {} {}", v(d.direction), exact(d.amplitude),
                       exact(d.frequency), exact(d.phase));
  case PlateDriver::Motion::rotate:
    return fmt::format(" rotate {} {}", v(d.pivot), v(d.angular_velocity));
  case PlateDriver::Motion::translate:
    break;
  }
  return " velocity " + v(d.velocity);
}

std::string laws_and_walls(const Scenario3& s, const BuiltScenario3& b) {
  const Simulation3Section& sim = s.simulation;
  const bool impact =
      with_normal_law(sim.normal_law, []<class N>() { return N::damping_needs_impact_speed; });
  std::string out = fmt::format("pair_style granthesis {} {}{}\n", name_of(sim.normal_law),
                                name_of(sim.tangential_law),
                                impact ? " impact_speed " + exact(sim.impact_speed) : "");
  const auto material = [&](const std::string& name) {
    return b.scene.materials[material_index(s, name, "")];
  };
  out += fmt::format("pair_coeff {0} {0} {1}\npair_coeff {2} {2} {3}\n", sphere_type,
                     pair_coefficient_words(material(s.particles.material)), plate_type,
                     pair_coefficient_words(material(s.geometry.wall_material)));
  out += "\ngroup grains type 1\nfix integrate grains nve/sphere\n";
  const Vec3 g = b.scene.gravity;
  if (const double size = std::sqrt(dot(g, g)); size > 0.0)
    out += fmt::format("fix gravity grains gravity {} vector {} {} {}\n", exact(size),
                       exact(g.x / size), exact(g.y / size), exact(g.z / size));
  if (b.scene.plates.empty()) return out;
  out += "fix walls grains granthesis/wall";
  for (std::uint32_t w = 0; w < b.scene.plates.size(); ++w) {
    const Plane& p = b.scene.plates[w];
    out += fmt::format(" &\n  plane {} {} {} {} {} {} type {}", exact(p.centre.x),
                       exact(p.centre.y), exact(p.centre.z), exact(p.normal.x), exact(p.normal.y),
                       exact(p.normal.z), plate_type);
    for (const PlateDriver& d : b.scene.drivers)
      if (d.plate == w) out += motion_words(d);
  }
  return out + "\nfix_modify walls energy yes\n";
}

std::string deck(const Scenario3& s, const BuiltScenario3& b, const std::string& command) {
  const double dt = b.settings.timestep;
  const bool walls = !b.scene.plates.empty();
  std::string out = deck_header(s, b, command) + "\n";
  // the steps and intervals counted as the native 3D run counts them, so that the dumps fall on
  // the steps of its snapshots
  out += fmt::format("variable steps index {}\n", steps_until(s.simulation.duration, dt));
  if (s.output.snapshot_interval > 0.0)
    out += fmt::format("variable snapshot_every index {}\n",
                       std::max<std::uint64_t>(1, steps_until(s.output.snapshot_interval, dt)));
  const auto side = [&](int k) {
    return s.geometry.periodic[static_cast<std::size_t>(k)] ? 'p' : 'f';
  };
  out += fmt::format("\nunits si\ndimension 3\natom_style sphere\natom_modify map array\n"
                     "boundary {} {} {}\ncomm_modify vel yes\n",
                     side(0), side(1), side(2));
  // a law with a spring, or rolling resistance's: each rank computes its own atoms' contacts
  const bool rolling =
      std::ranges::any_of(s.materials, [](const Material& m) { return m.rolling_friction > 0.0; });
  if (keeps_history(s.simulation.tangential_law) || rolling) out += "newton off\n";
  out += fmt::format("read_data data.{0}\ninclude masses.{0}\n\n", s.name);
  out += laws_and_walls(s, b) + "\n";
  // the native skin: half the largest radius unless given
  const double skin =
      s.simulation.skin > 0.0 ? s.simulation.skin : 0.5 * b.scene.spheres.max_radius();
  out += fmt::format("neighbor {} bin\nneigh_modify delay 0 every 1 check yes\ntimestep {}\n\n",
                     exact(skin), exact(dt));
  // the coordination number as thermo.csv counts it: contacts per sphere, plates included
  out += "compute grains_ke grains ke\ncompute grains_rotation grains erotate/sphere\n"
         "compute contacts all contact/atom\n";
  out += walls ? "compute contact_parts grains reduce ave c_contacts f_walls\n"
                 "variable coordination equal c_contact_parts[1]+c_contact_parts[2]\n"
               : "compute coordination grains reduce ave c_contacts\n";
  // f_gravity: the grains' energy in gravity; f_walls[1]: the plates' work on them
  out += fmt::format("thermo_style custom step time c_grains_ke c_grains_rotation "
                     "{}coordination pe{}{}\nthermo {}\nthermo_modify norm no\n",
                     walls ? "v_" : "c_",
                     dot(b.scene.gravity, b.scene.gravity) > 0.0 ? " f_gravity" : "",
                     walls ? " f_walls[1]" : "",
                     std::max<std::uint64_t>(1, steps_until(s.output.thermo_interval, dt)));
  if (s.output.snapshot_interval > 0.0)
    out += fmt::format("dump snapshots all custom ${{snapshot_every}} dump.{}.lammpstrj id type "
                       "radius mass x y z vx vy vz omegax omegay omegaz\ndump_modify snapshots "
                       "sort id format float %.17g\n",
                       s.name);
  return out + "\nrun ${steps}\n";
}

} // namespace

std::string sphere_data_sections(const Spheres& p, const std::function<int(std::size_t)>& type_of) {
  std::string out = "Atoms # sphere\n\n";
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = p.radius[i];
    const double density = p.mass[i] / (4.0 / 3.0 * std::numbers::pi * r * r * r);
    out += fmt::format("{} {} {} {} {} {} {}\n", i + 1, type_of(i), exact(2.0 * r), exact(density),
                       exact(p.position[i].x), exact(p.position[i].y), exact(p.position[i].z));
  }
  out += "\nVelocities\n\n";
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 v = p.velocity[i], w = p.angular_velocity[i];
    out += fmt::format("{} {} {} {} {} {} {}\n", i + 1, exact(v.x), exact(v.y), exact(v.z),
                       exact(w.x), exact(w.y), exact(w.z));
  }
  return out;
}

void check_lammps_export(const Scenario3& s) {
  const std::string why = [&]() -> std::string {
    if (s.simulation.lever_arm != LeverArm::contact_point)
      return "key 'simulation.lever_arm': pair_style granthesis takes the lever arms to the "
             "contact point; allowed: contact_point";
    if (s.simulation.linear_damping != LinearDamping::never_attractive)
      return "key 'simulation.linear_damping': pair_style granthesis derives the linear dashpot "
             "as never_attractive; allowed: never_attractive";
    if (s.geometry.rough_floor)
      return "key 'geometry.rough_floor': the case does not freeze glued spheres yet; allowed: "
             "false";
    for (std::size_t k = 0; k < s.drivers.size(); ++k)
      if (s.drivers[k].cell)
        return "key 'drivers." + std::to_string(k) +
               ".type': the case does not write a deforming cell in 3D yet (LAMMPS' own are fix "
               "deform with remap x, and a triclinic box sheared by fix deform xy erate with "
               "remap v: docs/lammps.md); allowed: vibrate, translate, rotate";
    for (std::size_t k = 0; k < s.drivers.size(); ++k)
      if (s.drivers[k].servo)
        return "key 'drivers." + std::to_string(k) +
               ".type': a servo plate has no fix granthesis/wall motion (LAMMPS holds a load with "
               "a wall of particles under fix aveforce, LIGGGHTS with fix "
               "mesh/surface/stress/servo: docs/lammps.md); allowed: vibrate, translate, rotate";
    for (const Material& m : s.materials)
      if (m.rigid)
        return "key 'materials': material '" + m.name +
               "' is rigid, which pair_coeff does not express yet; allowed: rigid = false";
    return "";
  }();
  if (!why.empty()) throw InvalidArgument(why + exactly);
}

LammpsCase export_lammps(const Scenario3& s, const BuiltScenario3& built,
                         const std::string& command) {
  check_lammps_export(s);
  return {.name = s.name,
          .deck = deck(s, built, command),
          .data = data_file(s, built.scene),
          .masses = masses_file(built.scene),
          .scenario = to_toml(s)};
}

} // namespace talus
