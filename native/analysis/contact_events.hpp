#pragma once
// Contact events: each contact's life from first touch to separation, followed step by step,
// with its duration, peak force and overlap, and the approach and separation speeds. Looked at
// after every step; start and end are placed between steps by the overlap's rate, so a duration
// is good to far better than a timestep.
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "analysis/observables.hpp"
#include "simulation/simulation.hpp"

namespace talus {

/// One contact from its start to its end (or to now, while it still touches).
struct ContactEvent {
  std::uint64_t particle = 0;     ///< the grain's id (the lower id of a pair)
  std::int64_t partner = -1;      ///< the other grain's id, or -1 for a wall
  std::int64_t wall = -1;         ///< the wall segment's index, or -1 for a pair
  double start = 0.0;             ///< s: when the overlap became positive
  double end = 0.0;               ///< s: when it returned to zero (the last look while touching)
  double peak_normal_force = 0.0; ///< N
  double peak_overlap = 0.0;      ///< m
  double impact_speed = 0.0;      ///< m/s: d xi / dt at the first look (the approach speed)
  double rebound_speed = 0.0;     ///< m/s: -d xi / dt at the last look (the separation speed)
  bool touching = false;          ///< still in contact when written (at the end of a run)
  double duration() const { return end - start; }
};

class ContactEventLog {
public:
  /// Looks at the contacts of the current state: updates the open ones, opens the new ones and
  /// returns those that ended since the last look, in the order they opened.
  std::vector<ContactEvent> observe(const Simulation& sim);
  /// The contacts open now, with their end at the last look and touching = true.
  std::vector<ContactEvent> open_events() const;
  std::size_t open_count() const { return open_.size(); }
  /// Takes the velocities of the current state as those of the last look: a log that starts or
  /// resumes with a run calls it once, observe() after every look.
  void remember(const Simulation& sim);
  /// The world's walls were removed or added between looks (`to`: each old wall's new index, -1
  /// where it was removed): the contacts with a removed wall end at the last look (where the
  /// wall went) and are returned, in the order they opened; the others follow their wall.
  std::vector<ContactEvent> renumber_walls(const std::vector<std::int64_t>& to);
  /// The log's state as numbers, for a checkpoint, and back: a resumed run's events are the
  /// same as an uninterrupted one's.
  std::vector<double> save() const;
  void load(const std::vector<double>& state);

private:
  // (the lower grain id, the other id) for a pair; (the grain id, -1 - segment) for a wall
  using Key = std::pair<std::uint64_t, std::int64_t>;
  struct Open {
    ContactEvent event;
    double last_overlap = 0.0, last_rate = 0.0, last_deceleration = 0.0; ///< at the last look
    double last_elastic = 0.0;  ///< m/s^2: the elastic part of last_deceleration
    double last_exponent = 1.0; ///< p of the force's shape (contact_events.cpp)
    std::uint64_t order = 0;    ///< when it opened, for a stable output order
    std::uint64_t seen = 0;     ///< the look that last saw it
  };
  double approach_before(const Simulation& sim, const ContactRecord& c) const;

  std::map<Key, Open> open_;
  std::vector<Vec2> velocity_by_id_; ///< m/s, at the last look, by particle id
  std::uint64_t looks_ = 0, opened_ = 0;
  double last_time_ = 0.0;
};

} // namespace talus
