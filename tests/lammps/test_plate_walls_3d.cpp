// fix granthesis/wall in 3d (lammps-package/fix_granthesis_wall_3d.cpp): spheres in a box of
// plates, some of them driven, against the native 3D engine to rounding for every law pair; a
// sphere rolling on a plate with rolling resistance against its closed form; a sphere resting on
// a plate puts its weight on it; a sphere beyond a rectangle's edge falls past it; bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fix.h"
#include "modify.h"
#include "native3d.hpp"

namespace talus::lammps_test {
namespace {

constexpr double g_plate = 9.81;

// A plate of the scene, as the native engine and the fix's words give it.
struct PlateCase {
  Vec3 point, normal;
  double half_u = unbounded, half_v = unbounded;
  std::optional<PlateDriver> driver;
};

std::string fix_words(const std::vector<PlateCase>& plates) {
  const auto v = [&](const Vec3& a) { return words({exact(a.x), exact(a.y), exact(a.z)}); };
  std::string w = "fix walls all granthesis/wall";
  const auto add = [&](const std::string& more) { w.append(" ").append(more); };
  for (const PlateCase& p : plates) {
    add(words({"plane", v(p.point), v(p.normal), "type 1"}));
    if (p.half_u != unbounded) add(words({"extent", exact(p.half_u), exact(p.half_v)}));
    if (!p.driver) continue;
    const PlateDriver& d = *p.driver;
    switch (d.motion) {
    case PlateDriver::Motion::translate:
      add(words({"velocity", v(d.velocity)}));
      break;
    case PlateDriver::Motion::rotate:
      add(words({"rotate", v(d.pivot), v(d.angular_velocity)}));
      break;
    case PlateDriver::Motion::vibrate:
      add(words(
          {"vibrate", v(d.direction), exact(d.amplitude), exact(d.frequency), exact(d.phase)}));
      break;
    }
  }
  return w;
}

Simulation3 native_run(const std::string& normal, const std::string& tangential, const Material& m,
                       const std::vector<Sphere>& spheres, const std::vector<PlateCase>& plates,
                       double dt) {
  Scene3 scene = native_scene(m, spheres);
  scene.gravity = {0.0, 0.0, -g_plate};
  for (std::size_t k = 0; k < plates.size(); ++k) {
    const PlateCase& p = plates[k];
    scene.plates.push_back(make_plane(p.point, p.normal, p.half_u, p.half_v));
    if (!p.driver) continue;
    PlateDriver d = *p.driver;
    d.plate = static_cast<std::uint32_t>(k);
    scene.drivers.push_back(d);
  }
  return run_as_lammps(std::move(scene), normal, tangential, dt);
}

void set_up_lammps(LammpsInstance& l, const std::string& laws, const Material& m,
                   const std::vector<Sphere>& spheres, const std::vector<PlateCase>& plates,
                   double dt) {
  set_up_3d(l, laws, m, spheres, dt);
  l.commands({fix_words(plates), "fix_modify walls energy yes", "fix move all nve/sphere",
              "fix gravity all gravity " + exact(g_plate) + " vector 0 0 -1"});
}

// A 2.4 cm box of plates: a floor vibrating along a tilted direction, a whole side wall and a
// tilted one closing in, and an 8 mm square turning about a tilted axis in the middle, which the
// spheres meet on its face and edges. Six spheres just above the floor, four above the square,
// thrown with spins.
std::vector<PlateCase> box_of_plates() {
  std::vector<PlateCase> p;
  p.push_back({{0.0, 0.0, -0.01}, {0.0, 0.0, 1.0}, unbounded, unbounded, {}});
  p.back().driver = PlateDriver{.motion = PlateDriver::Motion::vibrate,
                                .direction = {0.2, 0.0, 1.0},
                                .amplitude = 2e-4,
                                .frequency = 60.0,
                                .phase = 0.3};
  p.push_back({{-0.012, 0.0, 0.0}, {1.0, 0.0, 0.0}, unbounded, unbounded, {}});
  p.push_back({{0.012, 0.0, 0.0}, {-1.0, 0.2, 0.0}, unbounded, unbounded, {}});
  p.back().driver =
      PlateDriver{.motion = PlateDriver::Motion::translate, .velocity = {-0.05, 0.0, 0.0}};
  p.push_back({{0.0, 0.0, 0.0}, {0.1, 0.3, 1.0}, 0.004, 0.004, {}});
  p.back().driver = PlateDriver{.motion = PlateDriver::Motion::rotate,
                                .pivot = {0.001, 0.0, 0.0},
                                .angular_velocity = {0.0, 2.0, 10.0}};
  return p;
}

std::vector<Sphere> thrown_spheres() {
  RandomStream rng(2026, 1207);
  std::vector<Vec3> sites;
  for (const double x : {-0.008, 0.0, 0.008})
    for (const double y : {-0.004, 0.004}) sites.push_back({x, y, -0.007});
  for (const double x : {-0.003, 0.003})
    for (const double y : {-0.0028, 0.0028}) sites.push_back({x, y, 0.004});
  std::vector<Sphere> out;
  for (const Vec3& site : sites) {
    Sphere s{};
    s.radius = 0.0025 * (1.0 + 0.1 * rng.uniform(-1.0, 1.0));
    s.mass = 5e-5 * (1.0 + 0.3 * rng.uniform(-1.0, 1.0));
    s.position = site;
    s.velocity = {0.3 * rng.uniform(-1.0, 1.0), 0.3 * rng.uniform(-1.0, 1.0),
                  -0.3 * rng.uniform(0.0, 1.0)};
    s.spin = {30.0 * rng.uniform(-1.0, 1.0), 30.0 * rng.uniform(-1.0, 1.0),
              30.0 * rng.uniform(-1.0, 1.0)};
    out.push_back(s);
  }
  return out;
}

// The fix and the native engine place the plates and find the touch points by the same lines
// (src/talus/plate.hpp) and share the kernel; they differ in the integrator's and the force sums'
// order, a few ulp a step, which every collision amplifies: over 20000 steps below 1e-14 m of
// positions, 1e-12 m/s of speeds and 1e-10 rad/s of spins (speeds about 0.3 m/s, spins 30 rad/s).
// The largest differences after `steps` of the scene in both engines, with material m.
Difference among_plates(const std::string& normal, const std::string& tangential, const Material& m,
                        int steps) {
  const std::vector<Sphere> spheres = thrown_spheres();
  const std::vector<PlateCase> plates = box_of_plates();
  const double dt = 1e-6;
  LammpsInstance l;
  set_up_lammps(l, normal + " " + tangential, m, spheres, plates, dt);
  Simulation3 s = native_run(normal, tangential, m, spheres, plates, dt);
  std::size_t on_plates = 0;
  for (int k = 0; k < steps; ++k) {
    s.step();
    on_plates += s.last_pass().on_plates;
  }
  EXPECT_GT(on_plates, 1000u) << "the spheres hardly touched the plates";
  l.command("run " + std::to_string(steps));
  const Difference d = between(l, s);
  std::printf("%s %s%s: %.2e m, %.2e m/s, %.2e rad/s\n", normal.c_str(), tangential.c_str(),
              m.rolling_friction > 0.0 ? ", rolling" : "", d.position, d.velocity, d.spin);
  return d;
}

// Both engines run the scene with material m for each normal law and each of `tangentials`,
// and agree to rounding (the bounds above).
void expect_rounding_among_plates(const Material& m, const std::vector<std::string>& tangentials) {
  for (const std::string normal : {"linear", "hertz"})
    for (const std::string& tangential : tangentials) {
      SCOPED_TRACE(normal + " " + tangential);
      const Difference d = among_plates(normal, tangential, m, 20000);
      EXPECT_LT(d.position, 1e-14);
      EXPECT_LT(d.velocity, 1e-12);
      EXPECT_LT(d.spin, 1e-10);
    }
}

TEST(PlateWalls3D, SpheresAmongDrivenPlatesAgreeWithTheNativeEngineToRounding) {
  Material m = spheres_material();
  m.tangential_damping = 2000.0; // the Coulomb law's viscous friction turns the spheres too
  expect_rounding_among_plates(m, {"coulomb", "cundall_strack", "mindlin"});
}

// The same with rolling resistance between the spheres and on the plates (the turning square's
// spin in the relative spin): rounding as above.
TEST(PlateWalls3D, RollingResistanceAgreesWithTheNativeEngineToRounding) {
  Material m = spheres_material();
  m.tangential_damping = 2000.0;
  m.rolling_friction = 0.1;
  expect_rounding_among_plates(m, {"coulomb", "cundall_strack"});
}

// A sphere set rolling on a floor with rolling resistance (rolling_friction mu_r): once the
// rolling spring has reached its cap mu_r R F_n, the sphere rolls without slipping and slows at
// a = mu_r g R^2 / (R^2 + I/m) = 5/7 mu_r g (I = 2/5 m R^2). The measured deceleration over the
// rolling phase, within 1% (the spring's build-up and the contact's small oscillations).
TEST(PlateWalls3D, ASphereRollingOnAPlateSlowsAtTheRollingResistancesRate) {
  Material m = spheres_material();
  m.rolling_friction = 0.05;
  m.friction = 0.5;
  const double r = 0.005, mass = 1e-3;
  const double rest = mass * g_plate / m.normal_stiffness; // linear law: the overlap at rest
  const double v0 = 0.2;
  LammpsInstance l;
  set_up_3d(l, "linear cundall_strack", m,
            {{{0.0, 0.0, r - rest}, {v0, 0.0, 0.0}, {0.0, v0 / r, 0.0}, r, mass}}, 1e-6, "f f f",
            "-0.5 0.5 -0.1 0.1 -0.1 0.1");
  l.commands({"fix walls all granthesis/wall plane 0 0 0 0 0 1 type 1", "fix move all nve/sphere",
              "fix gravity all gravity " + exact(g_plate) + " vector 0 0 -1",
              "run 20000"}); // the spring builds up and the contact settles
  const double t = 0.1;
  const double v1 = l.velocity(1)[0];
  l.command("run " + std::to_string(static_cast<int>(std::lround(t / 1e-6))));
  const double v2 = l.velocity(1)[0];
  const double expected = 5.0 / 7.0 * m.rolling_friction * g_plate;
  std::printf("rolling on a plate: %.6g m/s^2, expected %.6g\n", (v1 - v2) / t, expected);
  EXPECT_NEAR((v1 - v2) / t, expected, 0.01 * expected);
  EXPECT_NEAR(l.lmp()->atom->omega[l.index(1)][1] * r, v2, 1e-3 * v2); // rolling, not slipping
}

// A sphere at rest on a floor puts its weight on it (the fix's fourth value, z), and one just
// beyond a rectangle's edge falls past it: a rectangle is bounded.
TEST(PlateWalls3D, ARestingSpherePutsItsWeightOnThePlateAndARectangleHasEdges) {
  Material m = spheres_material();
  m.restitution = 0.3;
  const double r = 0.005, mass = 1e-3;
  LammpsInstance l;
  set_up_3d(l, "linear coulomb", m,
            {{{0.0, 0.0, r}, {}, {}, r, mass}, {{0.0, 0.02 + 1.01 * r, r}, {}, {}, r, mass}}, 1e-6);
  l.commands({"fix walls all granthesis/wall plane 0 0 0 0 0 1 type 1 extent 0.02 0.02",
              "fix move all nve/sphere",
              "fix gravity all gravity " + exact(g_plate) + " vector 0 0 -1",
              "thermo_style custom step f_walls[4]", "run 50000"});
  EXPECT_NEAR(l.lmp()->atom->x[l.index(1)][2], r - mass * g_plate / m.normal_stiffness, 1e-9);
  LAMMPS_NS::Modify* modify = l.lmp()->modify;
  EXPECT_NEAR(modify->fix[modify->find_fix("walls")]->compute_vector(3), -mass * g_plate,
              1e-6 * mass * g_plate);
  EXPECT_LT(l.lmp()->atom->x[l.index(2)][2], -r); // fell past the edge, below the plate
}

TEST(PlateWalls3D, BadInputNamesTheSettingAndTheAllowedValues) {
  const std::vector<std::string> deck{"dimension 3",
                                      "units si",
                                      "atom_style sphere",
                                      "boundary f f f",
                                      "comm_modify vel yes",
                                      "newton off",
                                      "region box block -1 1 -1 1 -1 1",
                                      "create_box 1 box",
                                      "create_atoms 1 single 0 0 0",
                                      "set atom * diameter 0.01",
                                      "set atom * density 2650",
                                      "pair_style granthesis linear coulomb",
                                      "pair_coeff 1 1 " +
                                          pair_coefficient_words(spheres_material())};
  const auto with = [&](const std::string& fix) {
    std::vector<std::string> d = deck;
    d.insert(d.end(), {"fix walls all granthesis/wall " + fix, "fix move all nve/sphere", "run 1"});
    return d;
  };
  expect_deck_error(
      with("segment -1 -0.5 1 -0.5 type 1"),
      "segment: a segment is a wall of dimension 2; allowed in this dimension: plane");
  expect_deck_error(with("plane 0 0 0 0 0 0 type 1"),
                    "plane 1: normal NX NY NZ = 0 0 0; allowed: a direction, not zero");
  expect_deck_error(with("plane 0 0 0 0 0 1"),
                    "plane 1: 'type T' must follow its point and normal");
  expect_deck_error(with("plane 0 0 0 0 0 1 type 1 extent 0.1 0"),
                    "plane 1: extent 0.1 0; allowed: both half-widths > 0 (m)");
  expect_deck_error(with("plane 0 0 0 0 0 1 type 1 velocity 0 0 1 rotate 0 0 0 0 0 1"),
                    "plane 1 is given a second motion (rotate); allowed: one motion per plane");
  expect_deck_error(with("plane 0 0 0 0 0 1 type 1 vibrate 0 0 0 0.001 10 0"),
                    "plane 1: vibrate DX DY DZ = 0 0 0; allowed: a direction, not zero");
  expect_deck_error(with("plane 0 0 0 0 0 1 type 1 vibrate 0 0 1 0.001 10"), "PHASE is missing");
  expect_deck_error(with("plane 0 0 0 0 0 1 type 2"), "type 2 does not exist; allowed: 1 to 1");
  expect_deck_error(with("velocity 0 0 1"), "velocity before any plane");
}

} // namespace
} // namespace talus::lammps_test
