// The Love-Weber stress of the grains (analysis/stress.hpp) against closed forms: grains on
// a floor, the weight of a settled bed, a gas's streaming stress, and principal values.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <sstream>

#include "analysis/observables.hpp"
#include "analysis/stress.hpp"
#include "io/checkpoint.hpp"
#include "scenario/build.hpp"
#include "scenario/file/load.hpp"
#include "support/run_dir.hpp"
#include "support/run_scenario.hpp"
#include "support/smooth_bed.hpp"
#include "support/thermo_rows.hpp"

namespace talus {
namespace {

constexpr double g_bed = 9.81;

// A frictionless bed settled in a box of frictionless walls, floor at y = 0, with its stress.
const std::string bed = std::string(testing::smooth_bed) + "[output]\nstress = true\n";

Simulation simulation_of(const Scenario& s) {
  BuiltScenario b = build_scenario(s);
  return Simulation(std::move(b.world), b.config);
}

// Two grains stacked on a floor, a small one (radius r2, mass m2) on a large one (r1, m1): each
// contact pushes along the vertical at its branch, so the upper grain has
// sigma_yy = m2 g r2 / (pi r2^2) and the lower (m1 + 2 m2) g r1 / (pi r1^2) (its floor carries
// both grains, its top presses down with the upper one's weight), and nothing else. The branches
// end at the middle of the overlaps: the tolerance covers overlaps of under 1e-4 radii.
TEST(Stress, StackedGrainsOnAFloorCarryTheirWeights) {
  const Scenario s = load_scenario(R"(
name = "stack"
[particles]
list = [ { position = [0.05, 0.01], radius = 0.01 }, { position = [0.05, 0.025], radius = 0.005 } ]
[geometry]
builder = "box"
width = 0.1
height = 0.1
)",
                                   "stack.toml");
  Simulation sim = simulation_of(s);
  sim.run(40000); // the grains settle on their contacts
  const Particles& p = sim.world().particles;
  const double m1 = p.mass[0], r1 = p.radius[0], m2 = p.mass[1], r2 = p.radius[1];
  const std::vector<Tensor2> each = particle_stresses(sim);
  const double lower = (m1 + 2.0 * m2) * g_bed / (std::numbers::pi * r1);
  const double upper = m2 * g_bed / (std::numbers::pi * r2);
  EXPECT_NEAR(each[0](1, 1), lower, 1e-4 * lower);
  EXPECT_NEAR(each[1](1, 1), upper, 1e-4 * upper);
  for (const Tensor2& t : each) {
    EXPECT_NEAR(t(0, 0), 0.0, 1e-9 * upper);
    EXPECT_NEAR(t(0, 1), 0.0, 1e-9 * upper);
  }
  // the region's contact part is the grains' weighted by their areas over the region's
  const RegionStress box = region_stress(sim, {0.0, 0.0}, {0.1, 0.1});
  const double weighted = std::numbers::pi * (r1 * r1 * each[0](1, 1) + r2 * r2 * each[1](1, 1));
  EXPECT_NEAR(box.contact(1, 1), weighted / 0.01, 1e-12 * lower);
  EXPECT_EQ(box.grains, 2u);
  EXPECT_EQ(box.contacts, 1u);
  EXPECT_NEAR(box.fabric(1, 1), 1.0, 1e-9); // one vertical contact
}

// A static bed's stress balances its weight: summing f l over every grain, the contacts between
// grains cancel (equal and opposite forces at one point), the smooth side walls push
// horizontally, and the floor pushes where it touches, so sigma_yy A = sum m g y over the grains
// less sum y f_y over the floor's contacts, whatever the packing (the virial theorem of
// statics). The shear part is symmetric (the grains' torques balance). The tolerance 1e-3
// covers the bed's residual vibration (settled to E_kin < 1e-9 sum m g R, its accelerations
// are not yet 0).
TEST(Stress, ASettledBedsStressIsItsWeightTimesItsHeight) {
  const Scenario s = load_scenario(bed, "bed.toml");
  const Simulation sim = simulation_of(s);
  const Particles& p = sim.world().particles;
  double moment = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i)) moment += p.mass[i] * g_bed * p.position[i].y;
  // the floor's pushes act at the middle of their overlaps, a little above y = 0
  for (const ContactRecord& c : contact_forces(sim))
    if (c.j < 0) moment -= c.point.y * c.force.y;
  const double area = 0.06 * 0.12;
  const RegionStress box = region_stress(sim, {0.0, 0.0}, {0.06, 0.12});
  EXPECT_EQ(box.grains, 120u);
  EXPECT_NEAR(box.contact(1, 1) * area, moment, 1e-3 * moment);
  // and to rounding with the bed's residual forces F_i (its elastic vibration, a part in 1e4
  // of the weight's moment here): the contacts push each grain with F_i - m_i g
  double exact = moment;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i)) exact += p.position[i].y * p.force[i].y;
  EXPECT_NEAR(box.contact(1, 1) * area, exact, 1e-9 * moment);
  EXPECT_NEAR(box.contact(0, 1), box.contact(1, 0), 1e-3 * box.contact(1, 1));
  EXPECT_GT(box.contact(0, 0), 0.0); // the bed pushes on the side walls too
  EXPECT_LT(box.kinetic.norm(), 1e-3 * box.contact.norm());
  // the fabric's trace is 1, its contacts between grains
  EXPECT_NEAR(box.fabric.trace(), 1.0, 1e-12);
  EXPECT_GT(box.contacts, 100u);
  // the per-grain stresses add up to the region's contact part
  Tensor2 sum = Tensor2::Zero();
  const std::vector<Tensor2> each = particle_stresses(sim);
  for (std::size_t i = 0; i < p.size(); ++i)
    sum += each[i] * std::numbers::pi * p.radius[i] * p.radius[i];
  EXPECT_LT((sum / area - box.contact).norm(), 1e-12 * box.contact.norm());
}

// Grains that do not touch have only the streaming stress, (1/A) sum m u u about their mean
// velocity: two equal grains moving apart along x at +-v have sigma_xx = 2 m v^2 / A; a common
// drift adds nothing.
TEST(Stress, AGasHasOnlyItsStreamingStress) {
  World w;
  w.add_particle({.position = {0.2, 0.5}, .radius = 0.01});
  w.add_particle({.position = {0.8, 0.5}, .radius = 0.01});
  w.particles.velocity[0] = {-1.0 + 3.0, 0.5};
  w.particles.velocity[1] = {1.0 + 3.0, 0.5};
  SimulationConfig c;
  c.timestep = 1e-5;
  const Simulation sim(w, c);
  const RegionStress s = region_stress(sim, {0.0, 0.0}, {1.0, 1.0});
  const double m = sim.world().particles.mass[0];
  EXPECT_NEAR(s.kinetic(0, 0), 2.0 * m, 1e-12 * m);
  EXPECT_NEAR(s.kinetic(1, 1), 0.0, 1e-12 * m);
  EXPECT_NEAR(s.kinetic(0, 1), 0.0, 1e-12 * m);
  EXPECT_EQ(s.contact, Tensor2::Zero());
}

// Principal values and the major direction of [[3, 1], [1, 1]]: 2 +- sqrt(2), at 22.5 degrees;
// an antisymmetric part does not count.
TEST(Stress, PrincipalValuesAndDirection) {
  Tensor2 t;
  t << 3.0, 1.5, 0.5, 1.0;
  const Principal p = principal(t);
  EXPECT_NEAR(p.major, 2.0 + std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(p.minor, 2.0 - std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(p.angle, std::numbers::pi / 8.0, 1e-14);
  t << 1.0, 0.0, 0.0, 4.0; // the major axis along y
  EXPECT_NEAR(principal(t).angle, std::numbers::pi / 2.0, 1e-14);
}

// A run with output.stress writes the stress columns into thermo.csv (the settled bed pushes:
// its pressure is positive, its major stress near vertical) and each grain's stress into the
// snapshots.
TEST(Stress, ARunRecordsItsStress) {
  const Scenario s = load_scenario(bed, "bed.toml",
                                   {"particles.count=60", "simulation.duration=0.01",
                                    "output.snapshot_interval=0.01", "output.picture=false"});
  const std::filesystem::path dir = testing::fresh_dir("stress_run");
  ASSERT_EQ(testing::run_quietly(s, dir), cli::exit_completed);
  std::map<std::string, double> last = testing::last_thermo_row(dir);
  ASSERT_TRUE(last.count("stress_yy") && last.count("fabric_xx"));
  EXPECT_GT(last["pressure"], 0.0);
  EXPECT_GT(last["stress_yy"], last["stress_xx"]);
  EXPECT_GT(std::abs(last["stress_major_angle"]), 45.0);
  EXPECT_NEAR(last["fabric_xx"] + last["fabric_yy"], 1.0, 1e-5);
  const std::string vtp = read_file((dir / "snapshots/particles_000001.vtp").string());
  EXPECT_NE(vtp.find("Name=\"stress\" NumberOfComponents=\"9\""), std::string::npos);
  std::filesystem::remove_all(dir);
}

// Named regions have columns of their own: a bed's lower half bears more than its upper half,
// and the two halves' contact stresses, weighted by their areas, make the whole box's (each
// grain's centre is in one of them).
TEST(Stress, NamedRegionsHaveTheirOwnColumns) {
  const Scenario s = load_scenario(std::string(bed) + R"(
[[output.stress_regions]]
name = "lower"
region = [0.0, 0.0, 0.06, 0.015]
[[output.stress_regions]]
name = "upper"
region = [0.0, 0.015, 0.06, 0.12]
)",
                                   "regions.toml",
                                   {"particles.count=60", "simulation.duration=0.01",
                                    "output.snapshot_interval=0", "output.picture=false"});
  const std::filesystem::path dir = testing::fresh_dir("stress_regions");
  ASSERT_EQ(testing::run_quietly(s, dir), cli::exit_completed);
  std::map<std::string, double> last = testing::last_thermo_row(dir);
  ASSERT_TRUE(last.count("lower_stress_yy") && last.count("upper_fabric_yy"));
  EXPECT_GT(last["lower_pressure"], last["upper_pressure"]);
  const double whole = last["stress_yy"] * 0.06 * 0.12;
  const double halves =
      last["lower_stress_yy"] * 0.06 * 0.015 + last["upper_stress_yy"] * 0.06 * 0.105;
  EXPECT_NEAR(halves, whole, 1e-8 * std::abs(whole)); // the columns' 10 digits
  std::filesystem::remove_all(dir);
  // a region without a name, twice the same name, or without output.stress is refused
  const auto refused = [&](const std::string& extra, const char* words) {
    try {
      load_scenario(std::string(bed) + extra, "bad.toml");
      ADD_FAILURE() << "accepted: " << extra;
    } catch (const ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused("[[output.stress_regions]]\nregion = [0, 0, 1, 1]\n",
          "key 'output.stress_regions.0.name'");
  refused("[[output.stress_regions]]\nname = \"a\"\nregion = [0, 0, 1, 1]\n"
          "[[output.stress_regions]]\nname = \"a\"\nregion = [0, 0, 1, 1]\n",
          "'a' is given twice");
}

// output.stress needs an area: where the geometry has none, its region must be given.
TEST(Stress, AStressWithoutAnAreaIsRefused) {
  const std::string none = R"(
name = "none"
[particles]
list = [ { position = [0.0, 0.0], radius = 0.01 } ]
[output]
stress = true
)";
  try {
    build_scenario(load_scenario(none, "none.toml"));
    ADD_FAILURE() << "accepted";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("key 'output.stress_region': needed"), std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(
      build_scenario(load_scenario(none + "stress_region = [-1, -1, 1, 1]\n", "region.toml")));
}

} // namespace
} // namespace talus
