#include "scenario/sediment.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "analysis/observables.hpp"
#include "scenario/file/toml_reader.hpp"
#include "simulation/thread_chooser.hpp"
#include "talus/error.hpp"

namespace talus {

void sediment(const Scenario& s, const std::vector<SegmentSpec>& gate, std::uint16_t wall_mat,
              double joint_distance, const SettleProgress& progress, BuiltScenario& out) {
  World& w = out.world;
  const SimulationConfig& c = out.config;
  World settling = w;
  for (const SegmentSpec& g : gate) settling.add_wall(g.a, g.b, wall_mat);
  join_segment_ends(settling.walls, joint_distance);
  Simulation sim(std::move(settling), c);
  double scale = 0.0;
  for (std::size_t i = 0; i < sim.world().particles.size(); ++i)
    if (sim.world().particles.is_free(i))
      scale += sim.world().particles.mass[i] * norm(w.gravity) * sim.world().particles.radius[i];
  if (scale == 0.0)
    throw ScenarioError("key 'packing.method': sedimentation needs gravity (simulation.gravity)");
  // looked at every 5 ms, or once at the end of a shorter settling (its step count is bounded:
  // check_step_count)
  const double max_time = s.packing.settle_max_time;
  const double chunk_steps =
      max_time < 0.005 ? std::ceil(max_time / c.timestep) : std::floor(0.005 / c.timestep);
  const auto chunk = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(chunk_steps));
  out.settled = false;
  ThreadChooser threads(sim.max_threads()); // a busy machine: one thread may settle faster
  const auto began = std::chrono::steady_clock::now();
  const auto seconds_since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  try {
    while (sim.time() < s.packing.settle_max_time) {
      sim.use_threads(threads.threads());
      const auto start = std::chrono::steady_clock::now();
      sim.run(chunk);
      threads.took(seconds_since(start), chunk, seconds_since(began));
      const double ke = energies(sim).kinetic();
      if (progress) progress(sim.time(), ke);
      if (sim.time() > 0.05 && ke < s.packing.settle_energy * scale) {
        out.settled = true;
        break;
      }
    }
  } catch (const InstabilityError& e) { // its time and step are the settling's, not the run's
    throw InstabilityError(std::string("while settling the packing (packing.method = "
                                       "\"sedimentation\"), before the run: ") +
                           e.what());
  }
  out.settle_time = sim.time();
  // by id: the settling run may have renumbered its particles (simulation.sort_every)
  const Particles& settled = sim.world().particles;
  for (std::size_t k = 0; k < settled.size(); ++k) {
    const std::uint32_t i = settled.id[k];
    if (!w.particles.is_free(i)) continue;
    w.particles.position[i] = settled.position[k];
    w.particles.angle[i] = settled.angle[k];
  }
}

} // namespace talus
