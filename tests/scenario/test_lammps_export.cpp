// talus export lammps: what the deck and the data file say of a built scenario, and the scenarios
// it refuses. (tests/lammps/export_test.py runs the exported cases in LAMMPS.)
#include <gtest/gtest.h>

#include <charconv>
#include <numbers>
#include <sstream>

#include <fmt/format.h>

#include "io/lammps_export.hpp"
#include "support/builtin_scenario.hpp"

namespace talus {
namespace {

using testing::builtin;

// A small silo of the shaken-silo experiment: particle walls vibrated, grains on a lattice.
const std::vector<std::string> small_shaken_silo{"simulation.tangential_law=coulomb",
                                                 "materials[0].tangential_damping=5000",
                                                 "packing.method=lattice", "particles.count=60"};

LammpsCase exported(const std::string& name, std::vector<std::string> set) {
  const Scenario s = builtin(name, set);
  return export_lammps(s, build_scenario(s), "talus export lammps (test)");
}

bool has_line(const std::string& text, const std::string& line) {
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);)
    if (l == line) return true;
  return false;
}

std::string refusal(const std::string& name, const std::vector<std::string>& set) {
  try {
    check_lammps_export(builtin(name, set));
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "(not refused)";
}

TEST(LammpsExport, DeckHasTheLawsMaterialsGroupsAndDriver) {
  const LammpsCase c = exported("silo_shake", small_shaken_silo);
  EXPECT_EQ(c.name, "silo_shake");
  EXPECT_TRUE(has_line(c.deck, "pair_style granthesis linear coulomb")) << c.deck;
  EXPECT_TRUE(has_line(c.deck, "group grains type 1")) << c.deck;
  EXPECT_TRUE(has_line(c.deck, "group drive1 type 2")) << c.deck;
  // A sin(2 pi f t) along y: A = 0.01 m, f = 10 Hz
  EXPECT_TRUE(has_line(c.deck, "fix drive1 drive1 move wiggle 0 0.01 0 0.1")) << c.deck;
  EXPECT_TRUE(has_line(c.deck, "fix integrate grains nve/sphere")) << c.deck;
  EXPECT_TRUE(has_line(c.deck, "fix gravity grains gravity 9.81 vector 0 -1 0")) << c.deck;
  EXPECT_NE(c.deck.find("pair_coeff 1 1 young"), std::string::npos);
  EXPECT_NE(c.deck.find("tangential_damping 5000 "), std::string::npos);
}

TEST(LammpsExport, DataFileHoldsTheBuiltParticlesExactly) {
  const Scenario s = builtin("silo_shake", small_shaken_silo);
  const BuiltScenario b = build_scenario(s);
  const LammpsCase c = export_lammps(s, b, "test");
  const Particles& p = b.world.particles;
  EXPECT_NE(c.data.find(std::to_string(p.size()) + " atoms\n"), std::string::npos);
  std::istringstream in(c.data.substr(c.data.find("Atoms # sphere\n\n") + 16));
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::string id, type, diameter, density, x, y;
    in >> id >> type >> diameter >> density >> x >> y;
    const auto value = [](const std::string& t) {
      double v = 0.0;
      std::from_chars(t.data(), t.data() + t.size(), v);
      return v;
    };
    ASSERT_EQ(id, std::to_string(i + 1));
    EXPECT_EQ(type, p.is_free(i) ? "1" : "2");
    EXPECT_EQ(value(x), p.position[i].x); // bit for bit: the shortest text that reads back
    EXPECT_EQ(value(y), p.position[i].y);
    EXPECT_EQ(0.5 * value(diameter), p.radius[i]);
    std::getline(in, id); // z
  }
  EXPECT_NE(c.masses.find("set atom 1 mass "), std::string::npos);
  EXPECT_NE(c.masses.find("set atom " + std::to_string(p.size()) + " mass "), std::string::npos);
}

TEST(LammpsExport, PhaseRotationAndTranslationBecomeFixMove) {
  std::vector<std::string> phased = small_shaken_silo;
  phased.push_back("drivers[0].phase=0.5");
  const LammpsCase v = exported("silo_shake", phased);
  EXPECT_NE(v.deck.find("fix drive1 drive1 move variable v_drive1_dx v_drive1_dy NULL"),
            std::string::npos)
      << v.deck;
  EXPECT_NE(v.deck.find("sin(62.83185307179586*time+0.5)"), std::string::npos) << v.deck;

  const LammpsCase drum = exported(
      "drum", {"simulation.tangential_law=coulomb", "geometry.walls=particles",
               "geometry.angular_velocity=-2", "packing.method=lattice", "particles.count=40"});
  // clockwise: the axis -z, the period 2 pi / 2 s
  EXPECT_NE(drum.deck.find("move rotate 0.1 0.1 0 0 0 -1 3.14159265358979"), std::string::npos)
      << drum.deck;

  const LammpsCase press =
      exported("force_network", {"simulation.tangential_law=coulomb", "geometry.walls=particles",
                                 "particles.count=40"});
  EXPECT_NE(press.deck.find("move linear 0 -0.1 0"), std::string::npos) << press.deck;
  EXPECT_NE(press.deck.find("group fixed_walls type 2"), std::string::npos) << press.deck;
}

TEST(LammpsExport, UniformFrostBecomesFixFrostHeave) {
  const Scenario s = builtin(
      "frost_heave",
      {"simulation.tangential_law=coulomb", "geometry.walls=particles",
       "geometry.wall_particle_radius=2e-5", "particles.list[0].position=[0.0025,0.00032]",
       "particles.list[1].position=[0.0055,0.00022]", "particles.list[2].position=[0.0085,0.00017]",
       "packing.method=lattice", "particles.count=50"});
  const BuiltScenario b = build_scenario(s);
  const LammpsCase c = export_lammps(s, b, "test");
  double scale = 0.0; // the native threshold: kinetic_threshold x sum(m g R) of the grains
  for (std::size_t i = 0; i < b.world.particles.size(); ++i)
    if (b.world.particles.is_free(i))
      scale += b.world.particles.mass[i] * 9.81 * b.world.particles.radius[i];
  const std::string expected =
      fmt::format("fix frost grains frost/heave epsilon {} factor 1.5 table 0 interval 0.03",
                  s.frost.kinetic_threshold * scale);
  EXPECT_NE(c.deck.find(expected), std::string::npos) << expected << "\n" << c.deck;
  EXPECT_NE(c.deck.find("initial_wait yes inertia sphere"), std::string::npos);
}

TEST(LammpsExport, RefusesWhatLammpsCannotExpress) {
  EXPECT_NE(
      refusal("frost_front", {"simulation.tangential_law=coulomb", "geometry.walls=particles"})
          .find("key 'frost.model'"),
      std::string::npos);
  for (const char* arm : {"radius", "granular"})
    EXPECT_NE(refusal("collisions", {std::string("simulation.lever_arm=") + arm})
                  .find(std::string("key 'simulation.lever_arm': the lever arms '") + arm +
                        "' are a convention of LAMMPS' own granular styles"),
              std::string::npos);
  EXPECT_EQ(refusal("collisions", {}), "(not refused)");
  // the sheared cell at a pressure: LAMMPS' barostats are other controllers
  EXPECT_NE(refusal("simple_shear", {}).find("a cell held at a pressure"), std::string::npos)
      << refusal("simple_shear", {});
}

// The shaken silo with segment walls: each vibrating segment with its driver's direction,
// amplitude, frequency and phase, at full precision.
TEST(LammpsExport, VibratingSegmentsKeepTheirDriversMotion) {
  const Scenario s = builtin(
      "silo_shake", {"geometry.walls=segments", "particles.count=20", "packing.method=lattice"});
  const BuiltScenario b = build_scenario(s);
  const LammpsCase c = export_lammps(s, b, "test");
  std::size_t vibrating = 0;
  for (const Driver& d : b.world.drivers) {
    const auto* v = std::get_if<Vibrate>(&d.motion);
    if (!v) continue;
    const std::string motion = fmt::format(" vibrate {} {} {} {} {}", v->direction.x,
                                           v->direction.y, v->amplitude, v->frequency, v->phase);
    for (const std::uint32_t k : d.targets.segments) {
      const Segment& w = b.world.walls[k];
      const std::string line =
          fmt::format("  segment {} {} {} {} type 2{}", w.a.x, w.a.y, w.b.x, w.b.y, motion);
      EXPECT_NE(c.deck.find(line), std::string::npos) << line << "\n" << c.deck;
      ++vibrating;
    }
  }
  EXPECT_GT(vibrating, 0u);
}

// Segment walls and Cundall-Strack: the walls as fix granthesis/wall, each segment with its
// material's type (a type without atoms) and its motion; newton off for the springs; the
// walls' energy in pe and their work in the thermo output.
TEST(LammpsExport, SegmentWallsBecomeFixGranthesisWall) {
  const Scenario s = builtin(
      "force_network", {"geometry.walls=segments", "particles.count=40", "packing.method=lattice"});
  const BuiltScenario b = build_scenario(s);
  const LammpsCase c = export_lammps(s, b, "test");
  ASSERT_EQ(b.world.walls.size(), 4u);
  EXPECT_NE(c.deck.find(" cundall_strack"), std::string::npos) << c.deck;
  EXPECT_TRUE(has_line(c.deck, "newton off")) << c.deck;
  EXPECT_TRUE(has_line(c.deck, "fix walls grains granthesis/wall &")) << c.deck;
  EXPECT_TRUE(has_line(c.deck, "fix_modify walls energy yes")) << c.deck;
  // every segment, at full precision, the moving lid with its velocity
  std::size_t lines = 0;
  for (const Segment& w : b.world.walls) {
    const std::string at = fmt::format("  segment {} {} {} {} type 2", w.a.x, w.a.y, w.b.x, w.b.y);
    const std::size_t k = c.deck.find(at);
    EXPECT_NE(k, std::string::npos) << at << "\n" << c.deck;
    lines += k != std::string::npos;
  }
  EXPECT_EQ(lines, 4u);
  EXPECT_NE(c.deck.find("type 2 velocity 0 -"), std::string::npos) << c.deck;
  EXPECT_NE(c.deck.find("pair_coeff 2 2 young"), std::string::npos) << c.deck;
  EXPECT_NE(c.deck.find(" f_walls[1]"), std::string::npos) << c.deck;
  // the coordination counts the wall segments too, which contact/atom does not see
  EXPECT_TRUE(has_line(c.deck, "compute contact_parts grains reduce ave c_contacts f_walls"))
      << c.deck;
  EXPECT_TRUE(has_line(c.deck, "variable coordination equal c_contact_parts[1]+c_contact_parts[2]"))
      << c.deck;
  EXPECT_NE(c.deck.find("c_grains_rotation v_coordination pe"), std::string::npos) << c.deck;
  // no atoms are made for the walls: the 40 grains alone, and a type for the walls' material
  EXPECT_EQ(c.data.find("\n41 "), std::string::npos);
  EXPECT_NE(c.data.find("2 atom types"), std::string::npos) << c.data.substr(0, 200);
}

} // namespace
} // namespace talus
