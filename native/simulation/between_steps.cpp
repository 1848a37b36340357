// What changes between steps besides the particles: the timestep's clock (the steps' times when
// the timestep changed during a run), and walls removed and added (Simulation::change_walls: an
// orifice opened by taking its gate away, a wall put up during an experiment).
#include <algorithm>
#include <cmath>
#include <string>

#include "simulation/simulation.hpp"
#include "talus/error.hpp"

namespace talus {

namespace {

// The wall contacts of the list without those of removed walls, the others renumbered; their
// springs stay with them.
void renumber_wall_contacts(NeighbourList& l, const std::vector<std::int64_t>& to) {
  std::vector<std::uint32_t> offset{0}, segment;
  std::vector<double> history, rolling;
  const bool springs = l.wall_history.size() == l.wall_segment.size();
  const bool angles = l.wall_rolling.size() == l.wall_segment.size();
  for (std::size_t i = 0; i + 1 < l.wall_offset.size(); ++i) {
    for (std::uint32_t e = l.wall_offset[i]; e < l.wall_offset[i + 1]; ++e) {
      const std::int64_t k = to[l.wall_segment[e]];
      if (k < 0) continue;
      segment.push_back(static_cast<std::uint32_t>(k));
      if (springs) history.push_back(l.wall_history[e]);
      if (angles) rolling.push_back(l.wall_rolling[e]);
    }
    offset.push_back(static_cast<std::uint32_t>(segment.size()));
  }
  if (l.wall_offset.empty()) offset.clear();
  l.wall_offset = std::move(offset), l.wall_segment = std::move(segment);
  if (springs) l.wall_history = std::move(history);
  if (angles) l.wall_rolling = std::move(rolling);
}

// Each surviving wall's reference ends (a, b) under its new index, then the added walls' ends
// as they are now.
std::vector<Vec2> renumbered_references(const std::vector<Vec2>& ref,
                                        const std::vector<std::int64_t>& to,
                                        const Segments& added) {
  std::vector<Vec2> out;
  for (std::size_t k = 0; k < to.size() && 2 * k + 1 < ref.size(); ++k)
    if (to[k] >= 0) out.push_back(ref[2 * k]), out.push_back(ref[2 * k + 1]);
  for (const Segment& s : added) out.push_back(s.a), out.push_back(s.b);
  return out;
}

} // namespace

std::uint64_t steps_until(double time, double dt) {
  return static_cast<std::uint64_t>(std::clamp(std::ceil(time / dt - 1e-9), 0.0, 1e18));
}

std::uint64_t Simulation::step_at(double time) const {
  return clock_step_ + steps_until(time - clock_time_, config_.timestep);
}

std::vector<std::int64_t> Simulation::change_walls(const std::vector<bool>& removed,
                                                   const Segments& added) {
  Segments& walls = world_.walls;
  if (removed.size() != walls.size())
    throw InvalidArgument("change_walls: " + std::to_string(removed.size()) + " flags for " +
                          std::to_string(walls.size()) + " walls");
  for (const Segment& s : added)
    if (s.material >= world_.materials.size())
      throw InvalidArgument("change_walls: an added wall's material " + std::to_string(s.material) +
                            " is not one of the " + std::to_string(world_.materials.size()) +
                            " materials");
  for (std::size_t d = 0; d < world_.drivers.size(); ++d)
    for (const std::uint32_t k : world_.drivers[d].targets.segments)
      if (removed[k])
        throw InvalidArgument("change_walls: wall " + std::to_string(k) + " is moved by driver " +
                              std::to_string(d) + "; a driven wall cannot be removed");
  std::vector<std::int64_t> to(walls.size(), -1);
  Segments kept;
  for (std::size_t k = 0; k < walls.size(); ++k)
    if (!removed[k]) to[k] = static_cast<std::int64_t>(kept.size()), kept.push_back(walls[k]);
  kept.insert(kept.end(), added.begin(), added.end());
  for (Driver& d : world_.drivers)
    for (std::uint32_t& k : d.targets.segments) k = static_cast<std::uint32_t>(to[k]);
  list_.segment_reference = renumbered_references(list_.segment_reference, to, added);
  renumber_wall_contacts(list_, to);
  walls = std::move(kept);
  index_force_blocks(list_); // which particles are late follows their wall contacts
  list_stale_ = true;        // built again before the next forces: the added walls' contacts
  drift_bound_ = unknown_drift;
  features_stale_ = true; // a scene may have gained or lost its walls
  return to;
}

} // namespace talus
