// Results are bit-identical for 1 and 2 threads and from run to run: forces are summed in a fixed
// order (no floating-point atomics), whatever the number of threads.
#include <gtest/gtest.h>

#include <cstring>

#include "scenario/pour_box.hpp"
#include "simulation/simulation.hpp"
#include "support/state_hash.hpp"

namespace talus {
namespace {

using testing::state_hash;

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
