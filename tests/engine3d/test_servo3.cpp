// A plate held at a load by a servo in 3D (engine3d/plate_servo.hpp, the 2D servo's rule):
// - a lid pressing a bed of frictionless spheres in a box periodic across, come to rest, carries
//   the load asked and the floor carries the load and the bed's weight (no side walls to take a
//   share);
// - a run restored from a checkpoint, the servo's controller with it, is the whole run to the bit;
// - the scenario keys: a servo holds one side at a force or a stress (a stress times the box's
//   face), and what it cannot take is refused by name; LAMMPS' export refuses it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/builtin_scenarios.hpp"
#include "io/checkpoint3.hpp"
#include "io/lammps_export3.hpp"
#include "scenario/file/load3.hpp"
#include "scenario3d/build3.hpp"

namespace talus {
namespace {

std::string builtin_pour3d() {
  for (const auto& b : cli::builtin_scenarios())
    if (b.name == "pour3d") return std::string(b.text);
  ADD_FAILURE() << "no built-in pour3d";
  return {};
}

// pour3d's spheres, frictionless, one layer of them in a box periodic along x and y under a lid
// held at `stress` Pa by a servo.
Scenario3 pressed_bed(const std::vector<std::string>& more = {}) {
  std::vector<std::string> set{"particles.count=40",
                               "geometry.box=[0, 0, 0, 0.03, 0.03, 0.02]",
                               "geometry.periodic=xy",
                               "geometry.open_top=false",
                               "simulation.tangential_law=none",
                               "simulation.timestep_factor=20",
                               "drivers=[{type='servo', target='lid', stress=100.0}]"};
  set.insert(set.end(), more.begin(), more.end());
  return load_scenario3(builtin_pour3d(), "pressed bed", set);
}

std::uint64_t steps_for(double seconds, const Settings3& c) {
  return static_cast<std::uint64_t>(seconds / c.timestep);
}

TEST(Servo3, HoldsTheLoadItIsAskedAndTheFloorCarriesItWithTheWeight) {
  const BuiltScenario3 b = build_scenario3(pressed_bed());
  ASSERT_EQ(b.scene.servos.size(), 1u);
  const double load = 100.0 * 0.03 * 0.03; // the stress times the lid's face
  EXPECT_DOUBLE_EQ(b.scene.servos[0].force, load);
  Simulation3 sim(b.scene, b.settings);
  sim.run(steps_for(0.2, b.settings));
  const Scene3& scene = sim.scene();
  double weight = 0.0, kinetic = 0.0;
  for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
    weight += scene.spheres.mass[i] * 9.81;
    kinetic += 0.5 * scene.spheres.mass[i] * norm2(scene.spheres.velocity[i]);
  }
  // at rest: the motion left is a speck of the lid's work over the bed's settling
  ASSERT_LT(kinetic, 1e-6 * load * 0.01) << "the bed has not come to rest";
  const PlateServo& servo = scene.servos[0];
  const Plane& lid = scene.plates[servo.plate];
  const Plane& floor = scene.plates[0];
  // the controller closes half the error a step; the bed's last trembling moves it by a few
  // parts in 1e5: 1e-4
  EXPECT_NEAR(lid.force.z, load, 1e-4 * load); // pushed up
  EXPECT_NEAR(-floor.force.z, load + weight, 1e-4 * (load + weight));
  // the lid came down to the bed: from z = 0.02 m to about two radii
  EXPECT_LT(lid.centre.z, 0.006);
  EXPECT_NEAR(lid.centre.z, 0.02 + servo.displacement * servo.direction.z, 1e-15);
}

TEST(Servo3, ARestoredRunIsTheWholeRun) {
  const BuiltScenario3 b = build_scenario3(pressed_bed({"simulation.integrator=gear"}));
  Simulation3 whole(b.scene, b.settings);
  whole.run(4000);
  Simulation3 first(b.scene, b.settings);
  first.run(2000);
  const Checkpoint3 c = decode_checkpoint3(
      encode_checkpoint3({first.state(), first.settings(), ""}), "the servo's checkpoint");
  ASSERT_EQ(c.state.scene.servos.size(), 1u);
  EXPECT_EQ(c.state.scene.servos[0].speed, first.scene().servos[0].speed);
  Simulation3 second = Simulation3::restore(c.state, c.settings);
  second.run(2000);
  const Spheres &a = whole.scene().spheres, &s = second.scene().spheres;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(a.position[i].x == s.position[i].x && a.position[i].y == s.position[i].y &&
                a.position[i].z == s.position[i].z)
        << i;
    EXPECT_TRUE(a.velocity[i].x == s.velocity[i].x && a.velocity[i].y == s.velocity[i].y &&
                a.velocity[i].z == s.velocity[i].z)
        << i;
  }
  const PlateServo &x = whole.scene().servos[0], &y = second.scene().servos[0];
  EXPECT_EQ(x.displacement, y.displacement);
  EXPECT_EQ(x.speed, y.speed);
  EXPECT_NE(x.speed, 0.0); // the lid was still coming down: its controller was carried over
}

TEST(Servo3, TheScenarioKeysAreReadOrRefusedByName) {
  const Scenario3 s = pressed_bed({"drivers=[{type='servo', target='floor', force=-0.5, "
                                   "max_speed=0.2, relaxation=0.25}]"});
  const BuiltScenario3 b = build_scenario3(s);
  ASSERT_EQ(b.scene.servos.size(), 1u);
  EXPECT_EQ(b.scene.servos[0].force, -0.5);
  EXPECT_EQ(b.scene.servos[0].max_speed, 0.2);
  EXPECT_EQ(b.scene.servos[0].relaxation, 0.25);
  EXPECT_EQ(b.scene.servos[0].direction.z, 1.0); // the floor presses up
  EXPECT_TRUE(b.scene.drivers.empty());
  EXPECT_EQ(to_toml(load_scenario3(to_toml(s), "resolved")), to_toml(s));
  EXPECT_EQ(pressed_bed().drivers[0].max_speed, 1.0); // simulation.impact_speed
  const auto says = [](const std::string& driver, const std::string& words) {
    try {
      pressed_bed({"drivers=[" + driver + "]"});
      ADD_FAILURE() << driver << " was taken";
    } catch (const ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << driver << ": " << e.what();
    }
  };
  says("{type='servo', target='walls', force=1.0}", "allowed: floor, lid");
  says("{type='servo', target='lid'}", "force (N) or stress (Pa), not both");
  says("{type='servo', target='lid', force=1.0, stress=1.0}", "not both");
  says("{type='servo', target='lid', force=1.0, relaxation=0.0}", "in (0, 1]");
  says("{type='servo', target='lid', force=1.0, max_speed=0.0}", "> 0 m/s");
  says("{type='servo', target='lid', force=1.0, direction=[0, 0, 1]}", "only a vibrate driver");
  says("{type='vibrate', target='lid', force=1.0}", "only a servo driver");
  says("{type='cell'}", "a cell needs strain_rate = [x, y, z] (1/s), pressure (Pa)");
  EXPECT_THROW(check_lammps_export(pressed_bed()), InvalidArgument);
}

} // namespace
} // namespace talus
