// The 3D step specialised to a frictionless scene whose spheres do not turn
// (Simulation3::step_description, turns_spheres): it leaves the torques and spins out, and a run
// with it is the general step's run to the bit (every sum of the general step adds zeros that
// the specialised one leaves out). Scenes with both integrators, both normal laws, one and two
// materials, a periodic axis, renumbering, a vibrating floor and a turning wall, on one and two
// threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "engine3d/simulation3.hpp"
#include "support/two_body.hpp"
#include "talus/closed_forms.hpp"
#include "talus/law_table.hpp"

namespace talus {
namespace {

using testing::elastic_material;

bool same(const std::vector<Vec3>& u, const std::vector<Vec3>& v) {
  return u.size() == v.size() && std::memcmp(u.data(), v.data(), u.size() * sizeof(Vec3)) == 0;
}

struct ShapeCase {
  Integrator integrator;
  NormalLaw normal_law;
  int materials;
  int threads;
};

// 300 frictionless spheres falling in a box periodic along x onto a floor vibrating at 50 Hz,
// beside a wall turning about the vertical, renumbered every 500 steps.
Simulation3 frictionless_bed(const ShapeCase& c, bool general) {
  Material m = elastic_material();
  m.restitution = 0.5;
  m.friction = 0.0;
  Material light = m;
  light.density = 0.5 * m.density;
  Scene3 scene;
  scene.materials = {m};
  if (c.materials == 2) scene.materials.push_back(light);
  scene.gravity = {0.0, 0.0, -9.81};
  scene.domain = {.lo = {0.0, 0.0, 0.0}, .hi = {0.02, 0.02, 0.2}, .periodic = {true, false, false}};
  scene.plates.push_back(make_plane({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}));
  scene.plates.push_back(make_plane({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}));
  scene.plates.push_back(make_plane({0.0, 0.02, 0.0}, {0.0, -1.0, 0.0}));
  scene.drivers.push_back(
      {.plate = 0, .motion = PlateDriver::Motion::vibrate, .amplitude = 2e-4, .frequency = 50.0});
  scene.drivers.push_back({.plate = 1,
                           .motion = PlateDriver::Motion::rotate,
                           .pivot = {0.01, 0.0, 0.0},
                           .angular_velocity = {0.0, 0.0, 0.05}});
  for (int k = 0; k < 300; ++k)
    scene.add_sphere(
        {.position = {0.002 + 0.004 * (k % 5), 0.002 + 0.004 * ((k / 5) % 5),
                      0.002 + 0.004 * (k / 25)},
         .radius = 1.5e-3 + 1e-4 * (k % 3),
         .material = static_cast<std::uint16_t>(c.materials == 2 ? k % 2 : 0),
         .velocity = {0.2 * ((k % 7) - 3), 0.1 * ((k % 3) - 1), -0.5 - 0.1 * (k % 4)}});
  const double mass = 2650.0 * 4.0 / 3.0 * 3.14159 * 1.5e-9;
  Simulation3 sim(std::move(scene),
                  {.timestep = linear_collision_time(m.normal_stiffness, 0.0, mass) / 30.0,
                   .integrator = c.integrator,
                   .normal_law = c.normal_law,
                   .tangential_law = law_id<Frictionless>,
                   .sort_interval = 500,
                   .threads = c.threads});
  sim.use_general_step(general);
  return sim;
}

class StepShape3 : public ::testing::TestWithParam<ShapeCase> {};

TEST_P(StepShape3, AFrictionlessRunWithoutRotationIsTheGeneralStepsToTheBit) {
  Simulation3 special = frictionless_bed(GetParam(), false);
  Simulation3 general = frictionless_bed(GetParam(), true);
  EXPECT_EQ(special.step_description().rfind("frictionless, no rotation", 0), 0u);
  EXPECT_EQ(general.step_description(), "general");
  std::size_t contacts = 0, on_plates = 0; // the most met at once
  for (int k = 0; k < 100; ++k) {
    special.run(100);
    general.run(100);
    contacts = std::max(contacts, special.contact_count());
    on_plates = std::max(on_plates, special.last_pass().on_plates);
  }
  const Spheres &a = special.scene().spheres, &b = general.scene().spheres;
  EXPECT_TRUE(same(a.position, b.position));
  EXPECT_TRUE(same(a.velocity, b.velocity));
  EXPECT_TRUE(same(a.force, b.force));
  EXPECT_TRUE(same(a.angular_velocity, b.angular_velocity));
  EXPECT_TRUE(same(a.torque, b.torque)); // the general step's torques are +0 too
  EXPECT_TRUE(a.id == b.id);
  for (std::size_t w = 0; w < special.scene().plates.size(); ++w)
    EXPECT_EQ(std::memcmp(&special.scene().plates[w].force, &general.scene().plates[w].force,
                          sizeof(Vec3)),
              0)
        << "plate " << w;
  // and the run did what it is meant to test: many contacts, on the plates too
  EXPECT_GT(contacts, 100u);
  EXPECT_GT(on_plates, 20u);
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, StepShape3,
    ::testing::Values(ShapeCase{Integrator::verlet, law_id<LinearSpringDashpot>, 1, 1},
                      ShapeCase{Integrator::gear, law_id<HertzViscoelastic>, 2, 2},
                      ShapeCase{Integrator::verlet, law_id<HertzViscoelastic>, 2, 2},
                      ShapeCase{Integrator::gear, law_id<LinearSpringDashpot>, 1, 2}),
    [](const ::testing::TestParamInfo<ShapeCase>& p) {
      const ShapeCase& c = p.param;
      return std::string(c.integrator == Integrator::gear ? "gear" : "verlet") + "_" +
             with_normal_law(c.normal_law, []<class N>() { return std::string(N::name); }) + "_" +
             std::to_string(c.materials) + "materials_" + std::to_string(c.threads) + "threads";
    });

TEST(StepShape3, OnlyAFrictionlessSceneAtRestInSpinLeavesRotationOut) {
  Scene3 scene;
  Material m = elastic_material();
  m.friction = 0.0;
  scene.materials = {m};
  scene.domain = {.lo = {0.0, 0.0, 0.0}, .hi = {1.0, 1.0, 1.0}};
  scene.add_sphere({.position = {0.5, 0.5, 0.5}, .radius = 0.01});
  scene.add_sphere({.position = {0.2, 0.5, 0.5}, .radius = 0.01, .kind = Kind::fixed});
  Settings3 frictionless{.timestep = 1e-5, .tangential_law = law_id<Frictionless>};
  EXPECT_FALSE(turns_spheres(scene, frictionless));
  // a fixed sphere's spin moves nothing without friction
  scene.spheres.angular_velocity[1] = {0.0, 0.0, 3.0};
  EXPECT_FALSE(turns_spheres(scene, frictionless));
  Settings3 coulomb = frictionless;
  coulomb.tangential_law = law_id<ViscousCoulomb>;
  EXPECT_TRUE(turns_spheres(scene, coulomb));
  Scene3 spinning = scene;
  spinning.spheres.angular_velocity[0] = {1.0, 0.0, 0.0};
  EXPECT_TRUE(turns_spheres(spinning, frictionless));
  Scene3 rolling = scene;
  rolling.materials[0].rolling_friction = 0.1;
  EXPECT_TRUE(turns_spheres(rolling, frictionless));
  // and what the run says it left out
  EXPECT_EQ(Simulation3(scene, frictionless).step_description(),
            "frictionless, no rotation, one material");
  EXPECT_EQ(Simulation3(spinning, frictionless).step_description(), "one material");
}

} // namespace
} // namespace talus
