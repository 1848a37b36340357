#include "run/scenario_change.hpp"

#include "scenario/build.hpp"
#include "scenario/file/load.hpp"
#include "scenario/file/stages.hpp"

namespace talus::run {

namespace {

// The scenario with what may change during a run set as in `like`: two scenarios that differ in
// something else still differ after this.
Scenario with_changeable_of(Scenario s, const Scenario& like) {
  s.simulation.gravity = like.simulation.gravity;
  s.simulation.tangential_law = like.simulation.tangential_law;
  s.simulation.duration = like.simulation.duration; // talus resume --duration
  s.materials = like.materials;
  s.geometry.angular_velocity = like.geometry.angular_velocity;
  s.geometry.lid_speed = like.geometry.lid_speed;
  for (std::size_t k = 0; k < s.drivers.size() && k < like.drivers.size(); ++k) {
    DriverSection& d = s.drivers[k];
    const DriverSection& l = like.drivers[k];
    d.velocity = l.velocity, d.angular_velocity = l.angular_velocity, d.amplitude = l.amplitude;
    d.frequency = l.frequency, d.phase = l.phase, d.direction = l.direction, d.centre = l.centre;
  }
  s.output.thermo_interval = like.output.thermo_interval;
  s.output.snapshot_interval = like.output.snapshot_interval;
  s.output.track_interval = like.output.track_interval;
  s.output.checkpoint_interval = like.output.checkpoint_interval;
  return s;
}

bool same_motion(const DriverSection& a, const DriverSection& b) {
  return a.velocity == b.velocity && a.angular_velocity == b.angular_velocity &&
         a.amplitude == b.amplitude && a.frequency == b.frequency && a.phase == b.phase &&
         a.direction == b.direction && a.centre == b.centre;
}

// A driver whose motion changed starts its new motion from where its targets are now: no jump
// (a vibration starts at its phase from there).
void change_drivers(SimulationState& state, const std::vector<DriverSection>& before,
                    const std::vector<DriverSection>& after) {
  World& w = state.world;
  for (std::size_t k = 0; k < after.size() && k < w.drivers.size(); ++k) {
    if (same_motion(before[k], after[k])) continue;
    Driver& d = w.drivers[k];
    d.motion = motion_of(after[k]);
    attach(d, w.particles, w.walls);
    d.start_time = state.time;
  }
}

} // namespace

void apply_scenario_change(Simulation& sim, const Scenario& before, const Scenario& after) {
  // the resolved texts compare every key; only the materials' densities are compared apart
  if (to_toml(with_changeable_of(before, after)) != to_toml(after))
    throw ScenarioError("a change made something change that cannot during a run; allowed: " +
                        changeable_keys_text());
  for (std::size_t k = 0; k < before.materials.size(); ++k)
    if (before.materials[k].density != after.materials[k].density ||
        before.materials[k].name != after.materials[k].name)
      throw ScenarioError("key 'materials." + std::to_string(k) +
                          "': its density and name cannot change during a run");
  // the engine mixes its pairs and chooses its step as it starts: it starts again from its
  // state, as a resume from a checkpoint here would
  SimulationConfig config = sim.config();
  config.tangential_law = after.simulation.tangential_law;
  SimulationState state = sim.state();
  state.world.gravity = after.simulation.gravity;
  change_drivers(state, all_drivers(before), all_drivers(after));
  const std::vector<Material> materials = engine_materials(after);
  for (std::size_t k = 0; k < materials.size(); ++k) state.world.materials[k] = materials[k];
  sim = Simulation::restore(std::move(state), config);
}

} // namespace talus::run
