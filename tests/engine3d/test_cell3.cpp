// The deforming periodic cell of spheres and its Lees-Edwards images (engine3d/cell3.hpp):
// - at a set strain rate the box's sides grow as exp(rate t) and every sphere keeps its place as
//   a fraction of the box (the affine remap), the strain the integral of the rate;
// - the list misses no contact while the box shrinks or its images slide past: the contacts
//   counted by the force pass are those a brute-force search over every image finds, each step;
// - a sphere in free flight that crosses the sliding side comes in with the images' slide
//   (the shear rate times the height) taken off its velocity along x, once for each height
//   crossed down (put back for each crossed up), to rounding after many crossings;
// - a contact through a sliding image is the same contact as with a sphere placed where the
//   image is, moving as it moves (to rounding);
// - held at a pressure, the spheres' mean stress measured by the stress analysis (contact and
//   kinetic) comes to the target;
// - threads and a restored checkpoint give the same bits; the scenario keys read back from the
//   resolved form, and what a cell cannot take is refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "analysis/stress3.hpp"
#include "engine3d/cell3.hpp"
#include "engine3d/simulation3.hpp"
#include "io/checkpoint3.hpp"
#include "io/lammps_export3.hpp"
#include "scenario/file/load3.hpp"
#include "scenario3d/build3.hpp"
#include "support/two_body.hpp"
#include "talus/closed_forms.hpp"

namespace talus {
namespace {

using testing::elastic_material;

constexpr double cell_length = 0.03, cell_radius = 1e-3; // m

Settings3 cell_settings(const Scene3& scene, double law_factor = 40.0) {
  const Material& m = scene.materials[0];
  const double mass = scene.spheres.mass.empty() ? 1e-5 : scene.spheres.mass[0];
  return {.timestep = linear_collision_time(m.normal_stiffness, 0.0, 0.5 * mass) / law_factor,
          .tangential_law = law_id<CundallStrack>,
          .threads = 1};
}

Scene3 periodic_box(double length = cell_length) {
  Scene3 scene;
  Material m = elastic_material();
  m.restitution = 0.5;
  m.friction = 0.4;
  scene.materials = {m};
  scene.domain = {
      .lo = {0.0, 0.0, 0.0}, .hi = {length, length, length}, .periodic = {true, true, true}};
  return scene;
}

TEST(Cell3, AtASetRateTheBoxGrowsAsTheExponentialAndCarriesTheSpheres) {
  Scene3 scene = periodic_box();
  for (int k = 0; k < 27; ++k) // a lattice of spacing 1 cm: no sphere touches another
    scene.add_sphere(
        {.position = {0.005 + 0.01 * (k % 3), 0.005 + 0.01 * (k / 3 % 3), 0.005 + 0.01 * (k / 9)},
         .radius = cell_radius});
  const Vec3 rate{0.5, -0.4, 0.2};
  scene.cell = Cell3{.strain_rate = rate};
  const Scene3 start = scene;
  Simulation3 sim(std::move(scene), cell_settings(start));
  const std::uint64_t steps = 2000;
  sim.run(steps);
  const double t = sim.time();
  const Domain3& d = sim.scene().domain;
  // each step multiplies by exp(rate dt): the product differs from exp(rate t) by a rounding a
  // step, a few parts in 1e13 after 2000 steps
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(component(d.size(), k), cell_length * std::exp(component(rate, k) * t),
                1e-11 * cell_length)
        << k;
    EXPECT_NEAR(component(sim.scene().cell->strain, k), component(rate, k) * t, 1e-12) << k;
  }
  const Spheres& s = sim.scene().spheres;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR((component(s.position[i], k) - component(d.lo, k)) / component(d.size(), k),
                  component(start.spheres.position[i], k) / cell_length, 1e-12)
          << i << " along " << k;
  EXPECT_EQ(sim.contact_count(), 0u);
}

// Touching pairs by brute force over all pairs, each through its nearest image: across y first
// (its offset along x with it), then along x and z (the box is three reaches long at least, so a
// touching pair touches through one image).
std::size_t touching_pairs(const Scene3& scene) {
  const Spheres& s = scene.spheres;
  const Domain3& d = scene.domain;
  const Vec3 l = d.size();
  std::size_t count = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      const Vec3 apart = s.position[i] - s.position[j];
      const int sy = static_cast<int>(std::nearbyint(apart.y / l.y));
      const int sx = static_cast<int>(std::nearbyint((apart.x - sy * d.shear_offset) / l.x));
      const int sz = static_cast<int>(std::nearbyint(apart.z / l.z));
      const double reach = s.radius[i] + s.radius[j];
      count += norm2(apart - d.image_shift(sx, sy, sz)) < reach * reach ? 1 : 0;
    }
  return count;
}

// Spheres at rest or moving at random (`speed` m/s at most along each axis) in a box that shrinks
// fast (and whose images slide past).
Simulation3 squeezed_gas(const Cell3& cell, double fastest, std::uint32_t seed) {
  Scene3 scene = periodic_box(6 * 5.4e-3);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.2e-3, 0.2e-3), speed(-fastest, fastest),
      size(1.8 * cell_radius, 2.2 * cell_radius);
  for (int k = 0; k < 216; ++k) // a jittered lattice of spacing 5.4 mm: most pairs out of reach
    scene.add_sphere({.position = Vec3{0.0027 + 0.0054 * (k % 6), 0.0027 + 0.0054 * (k / 6 % 6),
                                       0.0027 + 0.0054 * (k / 36)} +
                                  Vec3{jitter(rng), jitter(rng), jitter(rng)},
                      .radius = size(rng),
                      .velocity = {speed(rng), speed(rng), speed(rng)}});
  scene.cell = cell;
  const Settings3 settings = cell_settings(scene);
  return Simulation3(std::move(scene), settings);
}

struct Squeeze {
  Cell3 cell;
  double speed; // m/s; 0: only the cell's strain brings spheres together and the list's builds
};

class Cell3List : public ::testing::TestWithParam<Squeeze> {};

TEST_P(Cell3List, MissesNoContactWhileTheBoxShrinksOrItsImagesSlide) {
  Simulation3 sim = squeezed_gas(GetParam().cell, GetParam().speed, 3);
  std::size_t most = 0;
  const std::uint64_t builds = sim.list().builds;
  for (int step = 0; step < 1500; ++step) {
    sim.step();
    const std::size_t expected = touching_pairs(sim.scene());
    ASSERT_EQ(sim.contact_count(), expected) << "step " << step;
    most = std::max(most, expected);
  }
  EXPECT_GT(most, 10u); // the gas was squeezed into contacts
  EXPECT_GT(sim.list().builds, builds + 2);
}

INSTANTIATE_TEST_SUITE_P(
    Strains, Cell3List,
    ::testing::Values(Squeeze{{.strain_rate = {-40.0, -40.0, -40.0}}, 0.0},
                      Squeeze{{.strain_rate = {-40.0, -40.0, -40.0}}, 0.3},
                      Squeeze{{.strain_rate = {0.0, -40.0, -20.0}, .shear_rate = 200.0}, 0.3}),
    [](const ::testing::TestParamInfo<Squeeze>& which) {
      return std::string(which.index == 0   ? "IsotropicAtRest"
                         : which.index == 1 ? "IsotropicMoving"
                                            : "StrainedAndSheared");
    });

TEST(Cell3, ASphereCrossingTheSlidingSideTakesTheImagesSlideOff) {
  Scene3 scene = periodic_box();
  const double rate = 30.0, slide = rate * cell_length;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> at(0.0, cell_length), speed(-3.0, 3.0);
  for (int k = 0; k < 9; ++k) // each in a layer of its own: none ever touches another
    scene.add_sphere({.position = {at(rng), at(rng), 0.0015 + 0.0033 * k},
                      .radius = cell_radius,
                      .velocity = {speed(rng), speed(rng), 0.0}});
  scene.cell = Cell3{.shear_rate = rate};
  const Scene3 start = scene;
  const Settings3 settings = cell_settings(scene);
  Simulation3 sim(std::move(scene), settings);
  for (int k = 0; k < 20; ++k) {
    sim.run(4000);
    const Spheres& s = sim.scene().spheres;
    for (std::size_t i = 0; i < s.size(); ++i) {
      // free flight, but for the slide taken off (or put back) at each height crossed down (up)
      const int heights = s.image[i][1];
      ASSERT_NEAR(s.velocity[i].x + heights * slide, start.spheres.velocity[i].x, 1e-12) << i;
      ASSERT_NEAR(s.position[i].y + heights * cell_length,
                  start.spheres.position[i].y + start.spheres.velocity[i].y * sim.time(), 1e-12)
          << i;
    }
  }
  std::int32_t crossings = 0;
  for (const Image3& image : sim.scene().spheres.image) crossings += std::abs(image[1]);
  EXPECT_GT(crossings, 20) << "the spheres hardly crossed the sliding side";
  EXPECT_NEAR(sim.scene().cell->shear_strain, rate * sim.time(), 1e-9);
}

TEST(Cell3, TheKineticStressOfAShearedCellIsThatOfItsSpheresFluctuations) {
  Scene3 scene = periodic_box();
  const double rate = 30.0;
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> at(0.0, cell_length);
  for (int k = 0; k < 9; ++k) { // in the flow's profile about the middle, none touching another
    const Vec3 p{at(rng), 0.0015 + 0.0033 * k, at(rng)};
    scene.add_sphere({.position = p,
                      .radius = cell_radius,
                      .velocity = {rate * (p.y - 0.0015 - 0.0033 * 4.0) + 0.2, 0.0, 0.0}});
  }
  scene.cell = Cell3{.shear_rate = rate};
  const Settings3 settings = cell_settings(scene);
  const Simulation3 sim(std::move(scene), settings);
  const Domain3& d = sim.scene().domain;
  const RegionStress3 s = region_stress(sim, d.lo, d.hi);
  // the flow itself, were it counted: sum m (rate (y - <y>))^2 / V, about 0.3 Pa
  EXPECT_LT(s.kinetic.norm(), 1e-12);
}

// Sphere 0 near the top touching sphere 1's image from below, in a box whose images across y
// sit `offset` along and slide at rate * length; or, unsheared, sphere 1 put where that image is
// less a height, moving as it moves.
Simulation3 through_the_side(bool sheared) {
  Scene3 scene = periodic_box();
  const double offset = 0.0123, rate = 7.0;
  const Vec3 top{0.02, cell_length - 0.0004, 0.015};
  const Vec3 below{0.0082, 0.0014, 0.0149}; // its image: x + offset, y + the height
  const Vec3 v0{0.1, -0.2, 0.05}, v1{-0.3, 0.1, 0.2}, w0{10.0, 0.0, -5.0}, w1{0.0, 20.0, 3.0};
  scene.add_sphere(
      {.position = top, .radius = cell_radius, .velocity = v0, .angular_velocity = w0});
  if (sheared) {
    scene.domain.shear_offset = offset;
    scene.cell = Cell3{.shear_rate = rate};
    scene.add_sphere(
        {.position = below, .radius = cell_radius, .velocity = v1, .angular_velocity = w1});
  } else {
    scene.add_sphere({.position = below + Vec3{offset, 0.0, 0.0},
                      .radius = cell_radius,
                      .velocity = v1 + Vec3{rate * cell_length, 0.0, 0.0},
                      .angular_velocity = w1});
  }
  const Settings3 settings = cell_settings(scene);
  return Simulation3(std::move(scene), settings);
}

TEST(Cell3, AContactThroughASlidingImageIsTheContactWithASphereWhereTheImageIs) {
  Simulation3 sheared = through_the_side(true), plain = through_the_side(false);
  ASSERT_EQ(sheared.contact_count(), 1u);
  ASSERT_EQ(plain.contact_count(), 1u);
  const auto same = [](const Vec3& a, const Vec3& b, const char* what) {
    // the image's place and slide are sums in another order: rounding of the overlap
    const double scale = std::max(norm(a), norm(b));
    EXPECT_LT(norm(a - b), 1e-9 * scale) << what;
    EXPECT_GT(scale, 0.0) << what;
  };
  for (int step = 0; step < 3; ++step) {
    same(sheared.scene().spheres.force[0], plain.scene().spheres.force[0], "force");
    same(sheared.scene().spheres.torque[0], plain.scene().spheres.torque[0], "torque");
    same(sheared.scene().spheres.torque[1], plain.scene().spheres.torque[1], "partner's torque");
    sheared.step();
    plain.step();
  }
}

constexpr const char* pressed_gas = R"(
name = "pressed_gas"
[simulation]
dimension = 3
normal_law = "linear"
tangential_law = "none"
gravity = [0.0, 0.0, 0.0]
impact_speed = 0.5
threads = 1
[[materials]]
name = "grain"
density = 2650.0
normal_stiffness = 1.0e4
restitution = 0.3
friction = 0.0
[particles]
count = 200
material = "grain"
size = { distribution = "uniform", mean_radius = 0.005, spread = 0.001 }
[geometry]
periodic = "xyz"
box = [0.0, 0.0, 0.0, 0.09, 0.09, 0.09]
[[drivers]]
type = "cell"
pressure = 200.0
max_strain_rate = 3.0
)";

TEST(Cell3, HeldAtAPressureTheSpheresPressAsHardAsAsked) {
  const BuiltScenario3 b = build_scenario3(load_scenario3(pressed_gas, "pressed gas"));
  Simulation3 sim(b.scene, b.settings);
  sim.run(static_cast<std::uint64_t>(0.5 / b.settings.timestep));
  double mean = 0.0;
  const int samples = 20;
  for (int k = 0; k < samples; ++k) {
    sim.run(200);
    const Domain3& d = sim.scene().domain;
    mean += region_stress(sim, d.lo, d.hi).total().trace() / 3.0 / samples;
  }
  // the controller closes half the error a step; what is left is the packing's trembling as it
  // settles at a stiffness k_n / (P d) = 5: a percent
  EXPECT_NEAR(mean, 200.0, 2.0);
  EXPECT_LT(sim.scene().cell->strain.x, -0.3); // it came from a lattice three times too loose
  EXPECT_EQ(sim.scene().cell->strain.x, sim.scene().cell->strain.z);
}

// A sheared cell held at a normal stress, 1200 spheres with some motion: enough for two threads.
Simulation3 sheared_gas(int threads) {
  Scene3 scene = periodic_box(0.0276);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> jitter(-0.1e-3, 0.1e-3), speed(-1.0, 1.0),
      size(0.9e-3, 1.1e-3);
  for (int k = 0; k < 1200; ++k)
    scene.add_sphere(
        {.position = Vec3{0.00115 + 0.0023 * (k % 12), 0.00115 + 0.0023 * (k / 12 % 12),
                          0.00115 + 0.0023 * (k / 144)} +
                     Vec3{jitter(rng), jitter(rng), jitter(rng)},
         .radius = size(rng),
         .velocity = {speed(rng), speed(rng), speed(rng)}});
  scene.cell = Cell3{.pressure = 50.0, .max_strain_rate = 5.0, .shear_rate = 20.0};
  Settings3 settings = cell_settings(scene);
  settings.threads = threads;
  settings.sort_interval = 300;
  return Simulation3(std::move(scene), settings);
}

bool same_bits(const Simulation3& a, const Simulation3& b) {
  const Spheres &x = a.scene().spheres, &y = b.scene().spheres;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x.position[i].x != y.position[i].x || x.position[i].y != y.position[i].y ||
        x.position[i].z != y.position[i].z || x.velocity[i].x != y.velocity[i].x ||
        x.angular_velocity[i].z != y.angular_velocity[i].z)
      return false;
  return a.scene().domain.hi.y == b.scene().domain.hi.y &&
         a.scene().domain.shear_offset == b.scene().domain.shear_offset &&
         a.scene().cell->rate == b.scene().cell->rate;
}

TEST(Cell3, ThreadsAndARestoredCheckpointGiveTheSameBits) {
  Simulation3 one = sheared_gas(1), two = sheared_gas(2);
  ASSERT_EQ(two.threads(), 2);
  one.run(1000);
  two.run(1000);
  EXPECT_GT(one.contact_count(), 50u);
  EXPECT_NE(one.scene().cell->rate, 0.0);
  EXPECT_TRUE(same_bits(one, two));
  const Checkpoint3 c = decode_checkpoint3(encode_checkpoint3({one.state(), one.settings(), ""}),
                                           "the cell's checkpoint");
  ASSERT_TRUE(c.state.scene.cell.has_value());
  Simulation3 restored = Simulation3::restore(c.state, c.settings);
  one.run(700);
  restored.run(700);
  EXPECT_GT(one.list().builds, c.state.list.builds); // the offset came back at a build
  EXPECT_TRUE(same_bits(one, restored));
}

TEST(Cell3, TheEngineRefusesACellTheBoxCannotTake) {
  const auto refused = [](Scene3 scene, const std::string& words) {
    scene.add_sphere({.position = {0.01, 0.01, 0.01}, .radius = cell_radius});
    const Settings3 settings = cell_settings(scene);
    try {
      Simulation3 sim(std::move(scene), settings);
      ADD_FAILURE() << "taken: " << words;
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  Scene3 open_z = periodic_box();
  open_z.domain.periodic[2] = false;
  open_z.cell = Cell3{.pressure = 10.0, .max_strain_rate = 1.0};
  refused(open_z, "a pressure needs a box periodic along every axis");
  open_z.cell = Cell3{.strain_rate = {0.0, 0.0, 1.0}};
  refused(open_z, "strain_rate deforms an axis that is not periodic");
  Scene3 plates = periodic_box();
  plates.plates.push_back(make_plane({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}));
  plates.cell = Cell3{.shear_rate = 1.0};
  refused(plates, "they do not follow it");
  Scene3 wide = periodic_box();
  wide.cell = Cell3{.strain_rate = {1.0, 0.0, 0.0}, .shear_rate = 1.0};
  refused(wide, "a sheared cell keeps its width");
}

std::string cell_scenario(const std::string& driver, const std::string& more = "") {
  std::string text = pressed_gas;
  text.replace(text.find("[[drivers]]"), std::string::npos, more + "[[drivers]]\n" + driver);
  return text;
}

std::string refusal(const std::string& text) {
  try {
    load_scenario3(text, "cell.toml");
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "taken";
}

TEST(Cell3, TheScenarioKeysReadBackOrAreRefusedByName) {
  const Scenario3 s = load_scenario3(
      cell_scenario("type = 'cell'\npressure = 80.0\nmax_strain_rate = 2.0\nrelaxation = 0.25\n"
                    "shear_rate = 3.0\n"),
      "cell.toml");
  ASSERT_EQ(s.drivers.size(), 1u);
  EXPECT_TRUE(s.drivers[0].cell);
  EXPECT_EQ(to_toml(load_scenario3(to_toml(s), "resolved")), to_toml(s));
  const BuiltScenario3 b = build_scenario3(s);
  ASSERT_TRUE(b.scene.cell.has_value());
  EXPECT_EQ(b.scene.cell->pressure, 80.0);
  EXPECT_EQ(b.scene.cell->relaxation, 0.25);
  EXPECT_EQ(b.scene.cell->shear_rate, 3.0);
  EXPECT_TRUE(b.scene.plates.empty() && b.scene.drivers.empty());
  const Scenario3 rate =
      load_scenario3(cell_scenario("type = 'cell'\nstrain_rate = [1, 2, 3]\n"), "cell.toml");
  EXPECT_EQ(rate.drivers[0].strain_rate.z, 3.0);
  EXPECT_EQ(to_toml(load_scenario3(to_toml(rate), "resolved")), to_toml(rate));
  EXPECT_THROW(check_lammps_export(rate), InvalidArgument);
  const auto says = [](const std::string& text, const std::string& words) {
    const std::string e = refusal(text);
    EXPECT_NE(e.find(words), std::string::npos) << e;
  };
  says(cell_scenario("type = 'cell'\n"), "a cell needs strain_rate = [x, y, z]");
  says(cell_scenario("type = 'cell'\nstrain_rate = [1, 0, 0]\npressure = 1.0\n"), "not both");
  says(cell_scenario("type = 'cell'\npressure = 1.0\n"), "'drivers.0.max_strain_rate'");
  says(cell_scenario("type = 'cell'\nshear_rate = 1.0\nstrain_rate = [1, 0, 0]\n"),
       "keeps its width");
  says(cell_scenario("type = 'cell'\nshear_rate = 1.0\nrelaxation = 0.5\n"),
       "only a cell held at a pressure has it");
  says(cell_scenario("type = 'cell'\nshear_rate = 1.0\ntarget = 'floor'\n"), "no target");
  says(cell_scenario("type = 'cell'\nshear_rate = 1.0\n[[drivers]]\ntype = 'cell'\nshear_rate = "
                     "2.0\n"),
       "drivers.0 is a cell already");
  says(cell_scenario("type = 'servo'\ntarget = 'floor'\nforce = 1.0\nshear_rate = 1.0\n"),
       "only a cell driver has it");
  std::string plates = cell_scenario("type = 'cell'\nshear_rate = 1.0\n");
  plates.replace(plates.find("periodic = \"xyz\""), 16, "periodic = \"xy\"");
  says(plates, "a deforming cell needs a box with no plates");
  says(cell_scenario("type = 'cell'\nshear_rate = 1.0\n", "[output]\nenergy_ledger = true\n"),
       "'output.energy_ledger'");
}

} // namespace
} // namespace talus
