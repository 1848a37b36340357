// Grains added and removed between steps (Simulation::add_particles, remove_particles): the other
// grains keep their ids and their contacts' springs, a removed grain takes only its own contacts,
// and an added grain starts in free flight.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <vector>

#include "simulation/simulation.hpp"
#include "support/mixed_box.hpp"
#include "support/pairs_by_id.hpp"
#include "talus/error.hpp"

namespace talus {
namespace {

using testing::PairKey;

SimulationConfig config() {
  SimulationConfig c;
  c.timestep = 1.0e-5;
  c.integrator = Integrator::verlet;
  c.threads = 1;
  return c;
}

// Every touching pair's tangential spring, by the pair's ids.
std::map<PairKey, double> springs(const Simulation& s) {
  std::map<PairKey, double> out;
  testing::for_each_pair_by_id(s, [&](const PairKey& key, std::uint32_t e, bool) {
    if (s.neighbours().history[e] != 0.0) out[key] = s.neighbours().history[e];
  });
  return out;
}

// A settled-in box, and a copy of it: one is edited, both step once. The springs of one step
// depend on the pair's own predicted motion alone, so every pair the edit did not touch has the
// same spring, bit for bit, in both: a spring lost at the edit would start again from 0.
struct Twins {
  Simulation control{testing::mixed_box(), config()};
  Simulation edited = [this] {
    control.run(3000);
    return Simulation::restore(control.state(), control.config());
  }();
};

TEST(GrainEdits, ARemovedGrainTakesOnlyItsOwnContacts) {
  Twins t;
  const Particles& p = t.edited.world().particles;
  // the free grain with the most touching pairs
  std::map<std::uint32_t, int> touching;
  for (const auto& [key, s] : springs(t.edited))
    ++touching[std::get<0>(key)], ++touching[std::get<1>(key)];
  std::uint32_t gone = 0;
  for (const auto& [id, n] : touching)
    if (p.kind[id] == Kind::free && n > touching[gone]) gone = id; // mixed_box: id = index here
  ASSERT_GE(touching[gone], 3);
  std::vector<bool> removed(p.size(), false);
  removed[gone] = true;
  const std::vector<std::int64_t> to = t.edited.remove_particles(removed);
  EXPECT_EQ(to[gone], -1);
  EXPECT_EQ(to[gone + 1], static_cast<std::int64_t>(gone));
  ASSERT_EQ(p.size(), t.control.world().particles.size() - 1);
  t.control.step();
  t.edited.step();
  const auto before = springs(t.control), after = springs(t.edited);
  std::size_t compared = 0;
  for (const auto& [key, s] : before) {
    if (std::get<0>(key) == gone || std::get<1>(key) == gone) {
      EXPECT_EQ(after.count(key), 0u);
      continue;
    }
    ASSERT_EQ(after.count(key), 1u) << std::get<0>(key) << " " << std::get<1>(key);
    EXPECT_EQ(after.at(key), s);
    ++compared;
  }
  EXPECT_GT(compared, 100u);
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_NE(p.id[i], gone);
}

TEST(GrainEdits, AnAddedGrainFallsFreelyAndTheOthersKeepTheirSprings) {
  Twins t;
  const World& w = t.edited.world();
  const double top = w.domain.hi.y; // the box's lid height: nothing up there yet
  ParticleSpec g;
  g.position = {0.15, top - 0.01};
  g.radius = 0.004;
  g.velocity = {0.1, -0.2};
  g.mass = 0.05;
  g.inertia = 0.5 * g.mass * g.radius * g.radius;
  for (std::size_t i = 0; i < w.particles.size(); ++i)
    ASSERT_GT(norm(w.particles.position[i] - g.position), g.radius + w.particles.radius[i]);
  std::uint32_t largest = 0;
  for (const std::uint32_t id : w.particles.id) largest = std::max(largest, id);
  const std::size_t i = t.edited.add_particles({g});
  EXPECT_EQ(i, t.control.world().particles.size());
  EXPECT_EQ(w.particles.id[i], largest + 1);
  t.control.step();
  t.edited.step();
  EXPECT_EQ(springs(t.control), springs(t.edited));
  // velocity Verlet is exact for a constant force: its previous force starts as m g
  const double dt = t.edited.config().timestep;
  const Vec2 x = g.position + dt * g.velocity + 0.5 * dt * dt * w.gravity;
  EXPECT_NEAR(w.particles.position[i].x, x.x, 1e-15);
  EXPECT_NEAR(w.particles.position[i].y, x.y, 1e-15);
  EXPECT_NEAR(w.particles.velocity[i].y, g.velocity.y + dt * w.gravity.y, 1e-15);
}

TEST(GrainEdits, WallParticlesAndBadMaterialsAreRefused) {
  Twins t;
  ParticleSpec g;
  g.position = {0.15, 0.3};
  g.radius = 0.004;
  g.mass = 0.05;
  g.inertia = 1e-7;
  g.material = 7;
  EXPECT_THROW(t.edited.add_particles({g}), InvalidArgument);
  std::vector<bool> removed(t.edited.world().particles.size(), false);
  for (std::size_t i = 0; i < removed.size(); ++i)
    if (t.edited.world().particles.kind[i] != Kind::free) {
      removed[i] = true;
      break;
    }
  ASSERT_NE(std::find(removed.begin(), removed.end(), true), removed.end());
  EXPECT_THROW(t.edited.remove_particles(removed), InvalidArgument);
  EXPECT_THROW(t.edited.remove_particles({true}), InvalidArgument);
}

} // namespace
} // namespace talus
