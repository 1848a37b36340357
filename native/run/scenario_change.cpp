#include "run/scenario_change.hpp"

#include <algorithm>
#include <limits>

#include "run/wall_edit.hpp"
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
  s.simulation.timestep = like.simulation.timestep;
  s.simulation.timestep_factor = like.simulation.timestep_factor;
  s.geometry.gate = like.geometry.gate;
  s.geometry.segments = like.geometry.segments;
  s.simulation.duration = like.simulation.duration; // talus resume --duration
  s.materials = like.materials;
  s.geometry.angular_velocity = like.geometry.angular_velocity;
  s.geometry.lid_speed = like.geometry.lid_speed;
  for (std::size_t k = 0; k < s.drivers.size() && k < like.drivers.size(); ++k) {
    DriverSection& d = s.drivers[k];
    const DriverSection& l = like.drivers[k];
    d.velocity = l.velocity, d.angular_velocity = l.angular_velocity, d.amplitude = l.amplitude;
    d.frequency = l.frequency, d.phase = l.phase, d.direction = l.direction, d.centre = l.centre;
    d.force = l.force, d.stress = l.stress, d.max_speed = l.max_speed, d.relaxation = l.relaxation;
    d.slide_speed = l.slide_speed;
    d.strain_rate = l.strain_rate, d.pressure = l.pressure;
    d.max_strain_rate = l.max_strain_rate, d.shear_rate = l.shear_rate;
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
         a.direction == b.direction && a.centre == b.centre && a.force == b.force &&
         a.stress == b.stress && a.max_speed == b.max_speed && a.relaxation == b.relaxation &&
         a.slide_speed == b.slide_speed && a.strain_rate == b.strain_rate &&
         a.pressure == b.pressure && a.max_strain_rate == b.max_strain_rate &&
         a.shear_rate == b.shear_rate;
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
    attach(d, w);
    d.start_time = state.time;
  }
}

bool materials_differ(const Scenario& before, const Scenario& after) {
  Scenario with = before;
  with.materials = after.materials;
  return to_toml(with) != to_toml(before);
}

// The timestep `after` asks for in the world as it is now (the materials changed already), and
// the collision time it follows; the one in force when it asks for that.
std::pair<double, double> next_timestep(const Scenario& after, const World& w,
                                        const SimulationConfig& c, double collision_time) {
  double r_min = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < w.particles.size(); ++i)
    if (w.particles.is_free(i)) r_min = std::min(r_min, w.particles.radius[i]);
  if (r_min == std::numeric_limits<double>::max()) return {c.timestep, collision_time};
  const PairTable pairs(w.materials, after.simulation.impact_speed,
                        after.simulation.linear_damping);
  const double tc = shortest_collision_time(after, w, pairs, r_min);
  return {chosen_timestep(after, w, pairs, c, r_min, tc), tc};
}

} // namespace

std::vector<std::int64_t> apply_scenario_change(Simulation& sim, const Scenario& before,
                                                const Scenario& after, RunBook& book) {
  // the resolved texts compare every key; only the materials' densities are compared apart
  if (to_toml(with_changeable_of(before, after)) != to_toml(after))
    throw ScenarioError("a change made something change that cannot during a run; allowed: " +
                        changeable_keys_text());
  for (std::size_t k = 0; k < before.materials.size(); ++k)
    if (before.materials[k].density != after.materials[k].density ||
        before.materials[k].name != after.materials[k].name)
      throw ScenarioError("key 'materials." + std::to_string(k) +
                          "': its density and name cannot change during a run");
  // every check before the first change: a refused change leaves the run as it was
  const WallEdit walls = wall_edit(before, after, sim.world(), book.groups, book.stage);
  // the engine mixes its pairs and chooses its step as it starts: it starts again from its
  // state, as a resume from a checkpoint here would
  SimulationConfig config = sim.config();
  config.tangential_law = after.simulation.tangential_law;
  SimulationState state = sim.state();
  state.world.gravity = after.simulation.gravity;
  change_drivers(state, all_drivers(before), all_drivers(after));
  const std::vector<Material> materials = engine_materials(after);
  for (std::size_t k = 0; k < materials.size(); ++k) state.world.materials[k] = materials[k];
  if (before.simulation.timestep != after.simulation.timestep ||
      before.simulation.timestep_factor != after.simulation.timestep_factor ||
      materials_differ(before, after)) {
    const auto [dt, tc] = next_timestep(after, state.world, config, book.collision_time);
    if (dt != config.timestep) { // the steps from here on count their times from here
      config.timestep = dt;
      state.clock_time = state.time;
      state.clock_step = state.steps;
    }
    book.collision_time = tc;
  }
  sim = Simulation::restore(std::move(state), config);
  if (walls.groups.empty()) return {};
  return apply_wall_edit(sim, walls, book.groups);
}

} // namespace talus::run
