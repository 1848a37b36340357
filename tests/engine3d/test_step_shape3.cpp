// The 3D steps specialised to a scene (Simulation3::step_description): a frictionless scene whose
// spheres do not turn (turns_spheres) leaves the torques and spins out, a law without history the
// springs; a run with them is the general step's run to the bit (every sum of the general step
// adds zeros that the specialised one leaves out), and continues from a checkpoint to the bit.
// Scenes with both integrators, both normal laws, frictionless and history-free laws (with
// rolling resistance too), one and two materials, a periodic axis, renumbering, a vibrating floor
// and a turning wall, on one and two threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "engine3d/simulation3.hpp"
#include "io/checkpoint3.hpp"
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
  TangentialLaw tangential_law;
  bool rolling; ///< rolling resistance
  int materials;
  int threads;
  const char* step; ///< what the specialised step leaves out
};

// 300 spheres falling in a box periodic along x onto a floor vibrating at 50 Hz,
// beside a wall turning about the vertical, renumbered every 500 steps.
Simulation3 falling_bed(const ShapeCase& c, bool general) {
  Material m = elastic_material();
  m.restitution = 0.5;
  m.friction = c.tangential_law == law_id<Frictionless> ? 0.0 : 0.4;
  m.rolling_friction = c.rolling ? 0.05 : 0.0;
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
                   .tangential_law = c.tangential_law,
                   .sort_interval = 500,
                   .threads = c.threads});
  sim.use_general_step(general);
  return sim;
}

class StepShape3 : public ::testing::TestWithParam<ShapeCase> {};

bool same_run(const Simulation3& a, const Simulation3& b) {
  const Spheres &p = a.scene().spheres, &q = b.scene().spheres;
  bool plates = true;
  for (std::size_t w = 0; w < a.scene().plates.size(); ++w)
    plates = plates &&
             std::memcmp(&a.scene().plates[w].force, &b.scene().plates[w].force, sizeof(Vec3)) == 0;
  // the general step's torques are +0 where the specialised one sums none
  return same(p.position, q.position) && same(p.velocity, q.velocity) && same(p.force, q.force) &&
         same(p.angular_velocity, q.angular_velocity) && same(p.torque, q.torque) && p.id == q.id &&
         plates && a.time() == b.time();
}

TEST_P(StepShape3, ARunInTheSpecialisedStepIsTheGeneralStepsToTheBit) {
  Simulation3 special = falling_bed(GetParam(), false);
  Simulation3 general = falling_bed(GetParam(), true);
  EXPECT_EQ(special.step_description(), GetParam().step);
  EXPECT_EQ(general.step_description(), "general");
  EXPECT_TRUE(special.list().spring.empty() && special.list().plate_spring.empty());
  EXPECT_EQ(general.list().spring.size(), general.list().pair_count());
  std::size_t contacts = 0, on_plates = 0; // the most met at once
  std::string halfway;
  for (int k = 0; k < 100; ++k) {
    special.run(100);
    general.run(100);
    contacts = std::max(contacts, special.contact_count());
    on_plates = std::max(on_plates, special.last_pass().on_plates);
    if (k == 49) halfway = encode_checkpoint3({special.state(), special.settings(), ""});
  }
  EXPECT_TRUE(same_run(special, general));
  // continued from a checkpoint (which holds no springs): the same run
  const Checkpoint3 c = decode_checkpoint3(halfway, "test");
  Simulation3 resumed = Simulation3::restore(c.state, c.settings);
  resumed.run(5000);
  EXPECT_TRUE(same_run(special, resumed));
  EXPECT_EQ(resumed.step_description(), GetParam().step);
  // and the run did what it is meant to test: many contacts, on the plates too
  EXPECT_GT(contacts, 100u);
  EXPECT_GT(on_plates, 20u);
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, StepShape3,
    ::testing::Values(ShapeCase{Integrator::verlet, law_id<LinearSpringDashpot>,
                                law_id<Frictionless>, false, 1, 1,
                                "frictionless, no rotation, one material"},
                      ShapeCase{Integrator::gear, law_id<HertzViscoelastic>, law_id<Frictionless>,
                                false, 2, 2, "frictionless, no rotation"},
                      ShapeCase{Integrator::verlet, law_id<HertzViscoelastic>,
                                law_id<ViscousCoulomb>, false, 2, 2, "history-free"},
                      ShapeCase{Integrator::gear, law_id<LinearSpringDashpot>,
                                law_id<ViscousCoulomb>, true, 1, 2, "history-free, one material"}),
    [](const ::testing::TestParamInfo<ShapeCase>& p) {
      const ShapeCase& c = p.param;
      return std::string(c.integrator == Integrator::gear ? "gear" : "verlet") + "_" +
             with_normal_law(c.normal_law, []<class N>() { return std::string(N::name); }) + "_" +
             with_tangential_law(c.tangential_law, []<class T>() { return std::string(T::name); }) +
             (c.rolling ? "_rolling_" : "_") + std::to_string(c.materials) + "materials_" +
             std::to_string(c.threads) + "threads";
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
  EXPECT_EQ(Simulation3(spinning, frictionless).step_description(), "frictionless, one material");
}

} // namespace
} // namespace talus
