// Results are bit-identical for 1 and 2 threads and from run to run: forces are summed in a fixed
// order (no floating-point atomics), whatever the number of threads.
#include <gtest/gtest.h>

#include <cstring>

#include "scenario/pour_box.hpp"
#include "simulation/simulation.hpp"

namespace talus {
namespace {

// FNV-1a over the raw bytes of every evolving field.
std::uint64_t state_hash(const Simulation& s) {
  std::uint64_t h = 1469598103934665603ULL;
  const auto mix = [&h](const void* data, std::size_t bytes) {
    const auto* c = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < bytes; ++k) h = (h ^ c[k]) * 1099511628211ULL;
  };
  const Particles& p = s.world().particles;
  mix(p.position.data(), p.position.size() * sizeof(Vec2));
  mix(p.velocity.data(), p.velocity.size() * sizeof(Vec2));
  mix(p.angular_velocity.data(), p.angular_velocity.size() * sizeof(double));
  mix(p.force.data(), p.force.size() * sizeof(Vec2));
  mix(s.neighbours().history.data(), s.neighbours().history.size() * sizeof(double));
  mix(s.neighbours().wall_history.data(), s.neighbours().wall_history.size() * sizeof(double));
  return h;
}

std::uint64_t poured_hash(int threads, Integrator integrator) {
  PourBoxSpec spec;
  spec.count = 400;
  PourBox box = build_pour_box(spec);
  box.config.threads = threads;
  box.config.min_particles_per_thread = 1; // really use the threads on this small system
  box.config.integrator = integrator;
  Simulation s(std::move(box.world), box.config);
  EXPECT_EQ(s.threads(), threads);
  s.run(20'000); // grains fall, collide and pile up: many contacts with history
  EXPECT_GT(s.neighbours().builds, 3U);
  return state_hash(s);
}

TEST(Determinism, OneAndTwoThreadsGiveBitIdenticalResults) {
  for (const Integrator integrator : {Integrator::gear, Integrator::verlet}) {
    const std::uint64_t one = poured_hash(1, integrator);
    EXPECT_EQ(one, poured_hash(2, integrator)) << to_string(integrator);
    EXPECT_EQ(one, poured_hash(1, integrator)) << "run to run, " << to_string(integrator);
  }
}

} // namespace
} // namespace talus
