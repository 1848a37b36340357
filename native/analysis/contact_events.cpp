#include "analysis/contact_events.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/observables.hpp"

namespace talus {

namespace {

// The time between a look and the touch (or the separation) of a contact whose overlap is
// `overlap` at the look, moving at `rate` towards it (the approach speed before a touch, the
// separation speed after) under the normal force's `deceleration`, taken as constant over so
// short a time: the root of overlap = rate t + deceleration t^2 / 2. At most the time between
// the looks.
double time_to_zero(double overlap, double rate, double deceleration, double between) {
  if (!(rate > 0.0)) return 0.0; // not moving the right way: the look itself is the best guess
  const double root = rate + std::sqrt(rate * rate + 2.0 * std::max(deceleration, 0.0) * overlap);
  return std::min(2.0 * overlap / root, between);
}

// The normal force per unit reduced mass at a look, split as the laws are: an elastic part that
// grows as xi^p and a dashpot part as xi^(p - 1) xi' (p = 1 linear, 3/2 Hertz), so that the
// speed a contact gains between a look and its touch or parting is integrated over the overlap
// rather than taken at the look's force.
struct ForceShape {
  double elastic = 0.0, dashpot = 0.0; ///< m/s^2
  double exponent = 1.0;               ///< p
};

ForceShape force_shape(const ContactRecord& c) {
  if (!(c.m_eff > 0.0)) return {};
  ForceShape f;
  f.elastic = c.elastic_force / c.m_eff;
  f.dashpot = c.normal_force / c.m_eff - f.elastic;
  if (c.elastic_force > 0.0)
    f.exponent = std::clamp(c.stiffness * c.overlap / c.elastic_force, 1.0, 2.0);
  return f;
}

// The speed the force took from the approach between the touch and a look `since` later, the
// overlap growing at a steady rate from zero: the mean of xi^p over it is 1 / (p + 1) of its value
// at the look, and of xi^(p - 1) 1 / p.
double speed_lost_since_touch(const ForceShape& f, double since) {
  return (f.elastic / (f.exponent + 1.0) + f.dashpot / f.exponent) * since;
}

// The speed the force adds to the parting over the `remaining` time from a look to the overlap's
// end, the overlap falling at a steady rate to zero. A never-attractive force ends where its
// dashpot part (negative while parting) cancels the elastic part: E z^p + D z^(p - 1) = 0 at
// z0 = xi / xi_look = -D / E.
double speed_gained_to_parting(const ForceShape& f, double remaining) {
  if (!(f.elastic + f.dashpot > 0.0) || !(f.elastic > 0.0)) return 0.0;
  const double p = f.exponent;
  const double z0 = f.dashpot < 0.0 ? std::min(-f.dashpot / f.elastic, 1.0) : 0.0;
  return remaining * (f.elastic * (1.0 - std::pow(z0, p + 1.0)) / (p + 1.0) +
                      f.dashpot * (1.0 - std::pow(z0, p)) / p);
}

} // namespace

std::vector<ContactEvent> ContactEventLog::observe(const Simulation& sim) {
  const Particles& p = sim.world().particles;
  const double now = sim.time(), between = now - last_time_;
  ++looks_;
  for (const ContactRecord& c : contact_forces(sim)) {
    const std::uint64_t id_i = p.id[c.i];
    Key key{id_i, c.j}; // a wall: -1 - segment, as in ContactRecord
    if (c.j >= 0) {
      const std::uint64_t id_j = p.id[static_cast<std::size_t>(c.j)];
      key = {std::min(id_i, id_j), static_cast<std::int64_t>(std::max(id_i, id_j))};
    }
    auto [it, fresh] = open_.try_emplace(key);
    Open& o = it->second;
    // the normal force slows the approach (and the separation): d^2 xi / dt^2 = -F_n / m_eff
    const double deceleration = c.m_eff > 0.0 ? c.normal_force / c.m_eff : 0.0;
    const ForceShape shape = force_shape(c);
    if (fresh) {
      o.order = opened_++;
      o.event.particle = key.first;
      o.event.partner = c.j >= 0 ? key.second : -1;
      o.event.wall = c.j >= 0 ? -1 : -1 - c.j;
      // a contact there at the first look (a packing) started then, as far as the log knows
      const double since =
          looks_ > 1 ? time_to_zero(c.overlap, c.overlap_rate, deceleration, between) : 0.0;
      o.event.start = now - since;
      // the speed at the touch: the approach at the last look, before it touched, where known;
      // else the speed now with what this force took since the touch
      const double before = approach_before(sim, c);
      o.event.impact_speed = looks_ > 1 && before > 0.0
                                 ? before
                                 : c.overlap_rate + speed_lost_since_touch(shape, since);
    }
    o.event.peak_normal_force = std::max(o.event.peak_normal_force, c.normal_force);
    o.event.peak_overlap = std::max(o.event.peak_overlap, c.overlap);
    o.event.end = now;
    o.event.rebound_speed = -c.overlap_rate;
    o.last_overlap = c.overlap;
    o.last_rate = c.overlap_rate;
    o.last_deceleration = deceleration;
    o.last_elastic = shape.elastic;
    o.last_exponent = shape.exponent;
    o.seen = looks_;
  }
  std::vector<std::pair<std::uint64_t, ContactEvent>> ended;
  for (auto it = open_.begin(); it != open_.end();) {
    if (it->second.seen == looks_) {
      ++it;
      continue;
    }
    const Open& o = it->second;
    ContactEvent e = o.event;
    const double since = time_to_zero(o.last_overlap, -o.last_rate, o.last_deceleration, between);
    e.end += since;
    // what the force still added after the look
    const ForceShape shape{o.last_elastic, o.last_deceleration - o.last_elastic, o.last_exponent};
    e.rebound_speed += speed_gained_to_parting(shape, since);
    ended.emplace_back(it->second.order, e);
    it = open_.erase(it);
  }
  std::sort(ended.begin(), ended.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<ContactEvent> out;
  out.reserve(ended.size());
  for (auto& [order, e] : ended) out.push_back(e);
  last_time_ = now;
  remember(sim);
  return out;
}

void ContactEventLog::remember(const Simulation& sim) {
  const Particles& p = sim.world().particles;
  std::uint32_t largest = 0;
  for (const std::uint32_t id : p.id) largest = std::max(largest, id);
  velocity_by_id_.assign(p.size() ? std::size_t{largest} + 1 : 0, Vec2{});
  for (std::size_t i = 0; i < p.size(); ++i) velocity_by_id_[p.id[i]] = p.velocity[i];
}

// The overlap's rate of a contact seen for the first time, from the velocities of the look
// before, when it did not touch yet: its approach speed free of the integrator's start-up at the
// touch (0 if unknown). A wall's velocity is its velocity now.
double ContactEventLog::approach_before(const Simulation& sim, const ContactRecord& c) const {
  const Particles& p = sim.world().particles;
  const auto velocity_before = [&](std::size_t i, Vec2& v) {
    if (p.id[i] >= velocity_by_id_.size()) return false;
    v = velocity_by_id_[p.id[i]];
    return true;
  };
  const Vec2 d = c.from - c.to;
  const double length = norm(d);
  Vec2 v_i, v_j;
  if (!(length > 0.0) || !velocity_before(c.i, v_i)) return 0.0;
  if (c.j >= 0) {
    if (!velocity_before(static_cast<std::size_t>(c.j), v_j)) return 0.0;
  } else {
    v_j = sim.world().walls[static_cast<std::size_t>(-1 - c.j)].velocity_at(c.to);
  }
  return -dot(v_i - v_j, d / length);
}

std::vector<ContactEvent> ContactEventLog::renumber_walls(const std::vector<std::int64_t>& to) {
  std::map<Key, Open> kept;
  std::vector<std::pair<std::uint64_t, ContactEvent>> ended;
  for (auto& [key, o] : open_) {
    if (key.second >= 0) { // a pair
      kept.emplace(key, o);
      continue;
    }
    const auto old = static_cast<std::size_t>(-1 - key.second);
    const std::int64_t now = old < to.size() ? to[old] : -1;
    if (now < 0) {
      ended.emplace_back(o.order, o.event);
      continue;
    }
    o.event.wall = now;
    kept.emplace(Key{key.first, -1 - now}, o);
  }
  open_ = std::move(kept);
  std::sort(ended.begin(), ended.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<ContactEvent> out;
  for (auto& [order, e] : ended) out.push_back(e);
  return out;
}

std::vector<ContactEvent> ContactEventLog::open_events() const {
  std::vector<std::pair<std::uint64_t, ContactEvent>> open;
  for (const auto& [key, o] : open_) {
    open.emplace_back(o.order, o.event);
    open.back().second.touching = true;
  }
  std::sort(open.begin(), open.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<ContactEvent> out;
  for (auto& [order, e] : open) out.push_back(e);
  return out;
}

// Layout: looks, opened, last_time, the number of open contacts, then per contact its key (2),
// its order and the event's and the last look's numbers (6 + 5). Ids and counts are exact in a
// double up to 2^53. A checkpoint of an earlier talus holds 3 numbers of the last look (no force
// shape): its contacts end as if all their force were elastic and linear.
std::vector<double> ContactEventLog::save() const {
  std::vector<double> s{static_cast<double>(looks_), static_cast<double>(opened_), last_time_,
                        static_cast<double>(open_.size())};
  for (const auto& [key, o] : open_) {
    const ContactEvent& e = o.event;
    s.insert(s.end(), {static_cast<double>(key.first), static_cast<double>(key.second),
                       static_cast<double>(o.order), e.start, e.end, e.peak_normal_force,
                       e.peak_overlap, e.impact_speed, e.rebound_speed, o.last_overlap, o.last_rate,
                       o.last_deceleration, o.last_elastic, o.last_exponent});
  }
  return s;
}

void ContactEventLog::load(const std::vector<double>& s) {
  constexpr std::size_t head = 4, earlier = 12, now = 14;
  if (s.size() < head) throw std::runtime_error("the checkpoint's contact event state is damaged");
  const auto open = static_cast<std::size_t>(s[3]);
  const std::size_t per_contact = s.size() == head + now * open ? now : earlier;
  if (s.size() != head + per_contact * open)
    throw std::runtime_error("the checkpoint's contact event state is damaged");
  looks_ = static_cast<std::uint64_t>(s[0]);
  opened_ = static_cast<std::uint64_t>(s[1]);
  last_time_ = s[2];
  open_.clear();
  for (std::size_t k = head; k < s.size(); k += per_contact) {
    const Key key{static_cast<std::uint64_t>(s[k]), static_cast<std::int64_t>(s[k + 1])};
    Open& o = open_[key];
    o.order = static_cast<std::uint64_t>(s[k + 2]);
    o.event.particle = key.first;
    o.event.partner = key.second >= 0 ? key.second : -1;
    o.event.wall = key.second >= 0 ? -1 : -1 - key.second;
    o.event.start = s[k + 3];
    o.event.end = s[k + 4];
    o.event.peak_normal_force = s[k + 5];
    o.event.peak_overlap = s[k + 6];
    o.event.impact_speed = s[k + 7];
    o.event.rebound_speed = s[k + 8];
    o.last_overlap = s[k + 9];
    o.last_rate = s[k + 10];
    o.last_deceleration = s[k + 11];
    o.last_elastic = per_contact == now ? s[k + 12] : o.last_deceleration;
    o.last_exponent = per_contact == now ? s[k + 13] : 1.0;
    o.seen = looks_;
  }
}

} // namespace talus
