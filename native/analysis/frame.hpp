#pragma once
// One moment of a run as plain arrays: what pictures are drawn from, whether it comes from a
// running Simulation or from a snapshot file read back (io/vtp_reader.hpp).
#include <cstdint>
#include <utility>
#include <vector>

#include "core/vec2.hpp"
#include "simulation/simulation.hpp"

namespace talus {

struct Frame {
  double time = 0.0;
  std::vector<std::uint32_t> id; ///< the particles' ids (stable over a run)
  std::vector<Vec2> position;
  std::vector<double> radius;
  std::vector<Vec2> velocity;
  std::vector<Vec2> force;
  std::vector<std::uint8_t> kind; ///< 0 free, 1 fixed, 2 moved
  std::vector<std::uint16_t> material;
  std::vector<double> mass; ///< kg (empty in snapshots written before it was recorded)
  std::vector<std::pair<Vec2, Vec2>> walls;
  /// Contacts: centre to centre (or to the wall), with the normal force in N; the force vector on
  /// the grain at `from`, the contact point and whether the partner is a wall (a segment or a
  /// wall particle) where the contact came with them (has_vector).
  struct Chain {
    Vec2 from;
    Vec2 to;
    double force;
    Vec2 force_on_from{};
    Vec2 point{};
    bool from_free = true; ///< the grain at `from` is free
    bool to_free = false;  ///< the partner at `to` is a free grain
    bool has_vector = false;
  };
  std::vector<Chain> chains;
};

/// The state of a simulation, contacts (with their forces) included.
Frame frame_of(const Simulation& sim);

} // namespace talus
