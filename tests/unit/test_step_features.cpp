// The step specialised to a scene (simulation/step_features.hpp) leaves out what the scene does
// not use, and must change nothing else: its results are bit-identical to the general step's,
// which does everything whatever the scene, on every scene, with either integrator, in fused
// runs and in single steps, and when the scene changes in the middle of a run.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>

#include "simulation/simulation.hpp"
#include "support/mixed_box.hpp"
#include "support/same_state.hpp"

namespace talus {
namespace {

using testing::expect_same_state;
using testing::mixed_box;

SimulationConfig config(Integrator integrator, TangentialLaw law) {
  SimulationConfig c;
  c.timestep = 5.0e-6; // omega dt = 0.12 for the stiffest pair: stable with Gear too
  c.integrator = integrator;
  c.tangential_law = law;
  c.threads = 2;
  c.min_particles_per_thread = 1;
  c.sort_interval = 50;
  return c;
}

// What is taken out of mixed_box (every kind of particle and contact, gravity, one material).
enum class Scene { everything, no_spin, no_gravity, two_materials, no_walls_no_drivers };

World scene(Scene s) {
  World w = mixed_box();
  Particles& p = w.particles;
  switch (s) {
  case Scene::everything:
    break;
  case Scene::no_spin: // the grains do not turn: a frictionless scene then never rotates
    std::fill(p.angular_velocity.begin(), p.angular_velocity.end(), 0.0);
    break;
  case Scene::no_gravity:
    std::fill(p.angular_velocity.begin(), p.angular_velocity.end(), 0.0);
    w.gravity = {0.0, 0.0};
    break;
  case Scene::two_materials: {
    Material hard = w.materials[0];
    hard.normal_stiffness *= 2.0;
    const std::uint16_t m = w.add_material(hard);
    for (std::size_t i = 0; i < p.size(); i += 3) p.material[i] = m;
    std::fill(p.angular_velocity.begin(), p.angular_velocity.end(), 0.0);
    break;
  }
  case Scene::no_walls_no_drivers:
    w.walls.clear();
    w.drivers.clear();
    std::fill(p.angular_velocity.begin(), p.angular_velocity.end(), 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) // the driven row stays, as fixed grains
      if (p.kind[i] == Kind::moved) p.kind[i] = Kind::fixed;
    break;
  }
  return w;
}

using Case = std::tuple<TangentialLaw, Integrator, Scene>;
class StepFeaturesCase : public ::testing::TestWithParam<Case> {};

TEST_P(StepFeaturesCase, TheSpecialisedStepIsBitIdenticalToTheGeneralStep) {
  const auto [law, integrator, s] = GetParam();
  Simulation special(scene(s), config(integrator, law));
  Simulation general(scene(s), config(integrator, law));
  general.use_general_step(true);
  ASSERT_EQ(general.step_description(), "general");
  // grains turning with no friction (Scene::everything) take the general step, springs and all
  const bool history_free = !special.step_features().history;
  EXPECT_EQ(history_free,
            !keeps_history(law) && !(law == law_id<Frictionless> && s == Scene::everything));
  special.run(300); // fused steps
  general.run(300);
  for (int k = 0; k < 20; ++k) special.step(), general.step(); // single steps
  expect_same_state(special, general, !history_free);
  EXPECT_EQ(special.world().walls.size(), general.world().walls.size());
  for (std::size_t w = 0; w < special.world().walls.size(); ++w)
    EXPECT_EQ(special.world().walls[w].force, general.world().walls[w].force) << "wall " << w;
  if (history_free) { // and the specialised list holds no springs
    EXPECT_TRUE(special.neighbours().history.empty());
    EXPECT_LT(special.footprint_bytes(), general.footprint_bytes());
  }
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  const auto [law, integrator, s] = info.param;
  static const char* scenes[] = {"everything", "no_spin", "no_gravity", "two_materials",
                                 "no_walls_no_drivers"};
  return std::string(name_of(law)) + "_" + std::string(to_string(integrator)) + "_" +
         scenes[static_cast<int>(s)];
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, StepFeaturesCase,
    ::testing::Combine(::testing::Values(law_id<Frictionless>, law_id<ViscousCoulomb>,
                                         law_id<CundallStrack>, law_id<MindlinNoSlip>),
                       ::testing::Values(Integrator::gear, Integrator::verlet),
                       ::testing::Values(Scene::everything, Scene::no_spin, Scene::no_gravity,
                                         Scene::two_materials, Scene::no_walls_no_drivers)),
    case_name);

TEST(StepFeatures, EachSceneGetsTheStepOfWhatItUses) {
  const auto features = [](Scene s, TangentialLaw law) {
    return Simulation(scene(s), config(Integrator::verlet, law)).step_description();
  };
  // grains given a spin with no friction to stop it: no step is specialised to that
  EXPECT_EQ(features(Scene::everything, law_id<Frictionless>), "general");
  EXPECT_EQ(features(Scene::no_spin, law_id<Frictionless>),
            "frictionless, no rotation, one material");
  EXPECT_EQ(features(Scene::no_gravity, law_id<Frictionless>),
            "frictionless, no rotation, one material, no gravity");
  EXPECT_EQ(features(Scene::two_materials, law_id<ViscousCoulomb>), "history-free");
  EXPECT_EQ(features(Scene::no_walls_no_drivers, law_id<CundallStrack>),
            "no walls, no drivers, one material");
  EXPECT_EQ(features(Scene::everything, law_id<MindlinNoSlip>), "one material");
}

// A scene in the specialised step and in the general step, edited alike and run for 100 steps
// after each edit, their states then compared.
struct SideBySide {
  Simulation special, general;
  SideBySide(const World& w, const SimulationConfig& c) : special(w, c), general(w, c) {
    general.use_general_step(true);
  }
  template <class Edit> void both(Edit&& edit) {
    edit(special);
    edit(general);
    special.run(100);
    general.run(100);
    expect_same_state(special, general, false);
  }
};

// The scene changes between runs: a grain is given a spin, a grain changes material. The step
// is chosen again, and the results stay those of the general step.
TEST(StepFeatures, TheStepIsChosenAgainWhenTheSceneChanges) {
  World w = scene(Scene::no_spin);
  w.add_material(w.materials[0]); // declared, of no grain yet
  for (const Integrator integrator : {Integrator::gear, Integrator::verlet}) {
    SideBySide s(w, config(integrator, law_id<Frictionless>));
    s.both([](Simulation&) {});
    EXPECT_EQ(s.special.step_description(), "frictionless, no rotation, one material");
    s.both([](Simulation& x) { x.edit_particles().set_material(40, 1); });
    EXPECT_EQ(s.special.step_description(), "frictionless, no rotation");
    s.both([](Simulation& x) {
      Particles& p = x.edit_world().particles;
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.is_free(i)) {
          p.angular_velocity[i] = 3.0;
          break;
        }
    });
    EXPECT_EQ(s.special.step_description(), "general");
  }
}

// A wall added to a scene that had none, then gravity switched off, with a history-free law:
// the step takes the wall pass up and leaves the weight out, as the general step does.
TEST(StepFeatures, TheStepIsChosenAgainWhenAWallIsAddedOrGravityGoes) {
  const World w = scene(Scene::no_walls_no_drivers);
  for (const Integrator integrator : {Integrator::gear, Integrator::verlet}) {
    SideBySide s(w, config(integrator, law_id<ViscousCoulomb>));
    s.both([](Simulation&) {});
    EXPECT_EQ(s.special.step_description(), "history-free, no walls, no drivers, one material");
    // a floor under the lowest grains, which they reach within the run
    s.both([](Simulation& x) { x.edit_world().add_wall({0.0, 0.011}, {0.3, 0.011}); });
    EXPECT_EQ(s.special.step_description(), "history-free, no drivers, one material");
    EXPECT_NE(s.special.world().walls[0].force.y, 0.0); // the grains did press on it
    s.both([](Simulation& x) { x.edit_world().gravity = {0.0, 0.0}; });
    EXPECT_EQ(s.special.step_description(), "history-free, no drivers, one material, no gravity");
  }
}

} // namespace
} // namespace talus
