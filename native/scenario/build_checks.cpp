#include "scenario/build_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <unistd.h>

#include <fmt/core.h>

#include "scenario/file/toml_reader.hpp"

namespace talus {

double memory_estimate(std::size_t particles) {
  // the process itself (code, libraries), then the particles: their arrays, the neighbour list
  // and contact history, and the checkpoint's copy of the state as it is written, which makes
  // the peak (fitted to the peaks measured in docs/performance.md, "Memory")
  return 16e6 + 1150.0 * static_cast<double>(particles);
}

std::string readable_bytes(double bytes) {
  if (bytes >= 1e9) return fmt::format("{:.3g} GB", bytes / 1e9);
  if (bytes >= 1e6) return fmt::format("{:.3g} MB", bytes / 1e6);
  return fmt::format("{:.3g} kB", bytes / 1e3);
}

// Refuses what the machine, or this process' limits (ulimit -v, -d), cannot hold, before
// allocating it.
void check_memory(std::size_t particles) {
  const double need = memory_estimate(particles);
  const double pages = static_cast<double>(::sysconf(_SC_PHYS_PAGES));
  const double page = static_cast<double>(::sysconf(_SC_PAGESIZE));
  double room = pages > 0 && page > 0 ? 0.8 * pages * page : HUGE_VAL;
  std::string what = "this machine has " + readable_bytes(room / 0.8);
  for (const auto& [resource, name] :
       {std::pair{RLIMIT_AS, "ulimit -v"}, {RLIMIT_DATA, "ulimit -d"}}) {
    rlimit limit{};
    if (::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) continue;
    // an address-space limit counts the libraries' and threads' mappings too, beyond what is
    // resident
    const double usable = 0.8 * static_cast<double>(limit.rlim_cur) - 200e6;
    if (usable < room) {
      room = usable;
      what = fmt::format("this process may use {} ({})",
                         readable_bytes(static_cast<double>(limit.rlim_cur)), name);
    }
  }
  if (need > room)
    throw ScenarioError(fmt::format("key 'particles.count': {} particles need about {}; {}",
                                    particles, readable_bytes(need), what));
}

// Double precision resolves a coordinate x to about |x| 2^-52. Beyond some distance from the
// origin that is no longer fine next to a grain (contact forces follow overlaps of a small share
// of a radius), and far enough out grains a diameter apart land on the same number. A scene
// reaching that far is refused here, rather than run on positions that cannot tell grains apart.
void check_position_resolution(const Scenario& s, const Rect& bounds, const Rect& fill,
                               double r_min) {
  double reach = 0.0;
  for (const Rect& r : {bounds, fill})
    for (const double c : {r.lo.x, r.lo.y, r.hi.x, r.hi.y}) reach = std::max(reach, std::abs(c));
  for (const ExplicitParticle& e : s.particles.list)
    reach = std::max({reach, std::abs(e.position.x), std::abs(e.position.y)});
  const double resolution = reach * std::numeric_limits<double>::epsilon();
  if (resolution > 1e-6 * r_min) {
    std::ostringstream msg;
    msg << "key 'geometry': the scene reaches " << reach << " m from the origin, " << reach / r_min
        << " radii of the smallest grain (" << r_min << " m); positions there are resolved only to "
        << resolution
        << " m, more than a millionth of that radius. Keep the container, packing.region and "
           "particles.list within "
        << 1e-6 / std::numeric_limits<double>::epsilon() << " radii of the origin";
    throw ScenarioError(msg.str());
  }
}

// A billion steps a second for a month is about 3e15 steps: a run of more could never end, and
// its step counts would not fit the integers that count them.
void check_step_count(const Scenario& s, double timestep) {
  constexpr double most_steps = 1e15;
  const bool settles = s.packing.method == "sedimentation";
  for (const auto& [time, key] :
       {std::pair{s.simulation.duration, "simulation.duration"},
        std::pair{settles ? s.packing.settle_max_time : 0.0, "packing.settle_max_time"}}) {
    if (time / timestep <= most_steps) continue;
    std::ostringstream msg;
    msg << "key '" << key << "': " << time << " s takes " << time / timestep
        << " steps of the timestep " << timestep
        << " s; allowed: at most 1e15 steps (a shorter time, or softer materials: the timestep "
           "follows the collision time)";
    throw ScenarioError(msg.str());
  }
}

// Listed grains may touch at the start but not overlap deeper than 1% of the smaller radius (walls:
// check_listed_grains_clear_of_walls).
void check_start_overlaps(const Scenario& s) {
  const auto& list = s.particles.list;
  for (std::size_t a = 0; a < list.size(); ++a) {
    for (std::size_t b = a + 1; b < list.size(); ++b) {
      const double overlap =
          list[a].radius + list[b].radius - norm(list[a].position - list[b].position);
      if (overlap > 0.01 * std::min(list[a].radius, list[b].radius) &&
          (list[a].kind == "free" || list[b].kind == "free"))
        throw ScenarioError("key 'particles.list': grains " + std::to_string(a) + " and " +
                            std::to_string(b) + " overlap by " + std::to_string(overlap) +
                            " m at the start; allowed: at most 1% of the smaller radius");
    }
  }
}

// Walls given by hand (extra segments, listed wall particles) must not leave an accidental gap
// a grain can slip through: an opening wider than the smallest grain's diameter but narrower
// than the largest's is refused. Wider openings (a silo's top, an orifice) are taken as meant;
// builders' walls have no gaps at all.
namespace {

// Whether a segment other than `self` touches point p (a joined end is no free end).
bool joined(const std::vector<SegmentSpec>& seg, std::size_t self, Vec2 p) {
  for (std::size_t k = 0; k < seg.size(); ++k) {
    if (k == self) continue;
    const Segment s{seg[k].a, seg[k].b};
    if (norm(p - closest_point(s, p)) <= 1e-9 * std::max(1.0, norm(seg[k].b - seg[k].a)))
      return true;
  }
  return false;
}

// Whether a grain of radius r centred at p would overlap a segment, or a fixed listed particle
// other than those in `skip`.
bool occupied(const Scenario& s, Vec2 p, double r, std::size_t skip_a, std::size_t skip_b) {
  for (const SegmentSpec& g : s.geometry.segments) {
    const Segment seg{g.a, g.b};
    if (norm(p - closest_point(seg, p)) < r) return true;
  }
  const auto& list = s.particles.list;
  for (std::size_t c = 0; c < list.size(); ++c)
    if (c != skip_a && c != skip_b && list[c].kind == "fixed" &&
        norm(p - list[c].position) < list[c].radius + r)
      return true;
  return false;
}

} // namespace

// A gap is an accident when a grain could pass it but not the largest (a wider one is taken as
// an opening meant, a silo's top say) and it is a real passage: between two free segment ends,
// or between two wall particles with nothing in their throat. A rough base of overlapping wall
// particles leaves gaps between next-but-one neighbours that the one between closes, and joined
// segments' ends are no gap.
void check_wall_gaps(const Scenario& s, double r_min, double r_max) {
  const auto gap_error = [&](const std::string& what, double gap) {
    throw ScenarioError(
        what + " leave a gap of " + std::to_string(gap) + " m, which a grain of diameter " +
        std::to_string(2.0 * r_min) +
        " m can pass; join them, or leave an opening wider than the largest grain (" +
        std::to_string(2.0 * r_max) + " m)");
  };
  const auto accidental = [&](double gap) { return gap >= 2.0 * r_min && gap < 2.0 * r_max; };
  const auto& seg = s.geometry.segments;
  for (std::size_t a = 0; a < seg.size(); ++a)
    for (std::size_t b = a + 1; b < seg.size(); ++b)
      for (const Vec2 p : {seg[a].a, seg[a].b})
        for (const Vec2 q : {seg[b].a, seg[b].b})
          if (accidental(norm(p - q)) && !joined(seg, a, p) && !joined(seg, b, q) &&
              !occupied(s, 0.5 * (p + q), r_min, SIZE_MAX, SIZE_MAX))
            gap_error("key 'geometry.segments': segments " + std::to_string(a) + " and " +
                          std::to_string(b),
                      norm(p - q));
  const auto& list = s.particles.list;
  for (std::size_t a = 0; a < list.size(); ++a) {
    if (list[a].kind != "fixed") continue;
    for (std::size_t b = a + 1; b < list.size(); ++b) {
      if (list[b].kind != "fixed") continue;
      const Vec2 d = list[b].position - list[a].position;
      const double distance = norm(d);
      const double gap = distance - list[a].radius - list[b].radius;
      if (!accidental(gap)) continue;
      // the middle of the throat between their surfaces, where a passing grain is freest
      const Vec2 middle = list[a].position + (list[a].radius + 0.5 * gap) / distance * d;
      if (!occupied(s, middle, r_min, a, b))
        gap_error("key 'particles.list': wall particles " + std::to_string(a) + " and " +
                      std::to_string(b),
                  gap);
    }
  }
}

// Listed grains must start inside the container and clear of its walls: segments and wall
// particles (the builder's or listed ones) overlapping a grain by more than 1% of the smaller
// radius are refused, as grains overlapping each other are.
void check_listed_grains_clear_of_walls(const Scenario& s, const World& w, const Rect& bounds) {
  const Particles& p = w.particles;
  const bool has_bounds = bounds.hi.x > bounds.lo.x && bounds.hi.y > bounds.lo.y;
  for (std::size_t k = 0; k < s.particles.list.size(); ++k) {
    const ExplicitParticle& e = s.particles.list[k];
    if (e.kind != "free") continue;
    const std::string grain = "key 'particles.list': grain " + std::to_string(k) + " at (" +
                              std::to_string(e.position.x) + ", " + std::to_string(e.position.y) +
                              ") m";
    if (has_bounds && (e.position.x < bounds.lo.x || e.position.x > bounds.hi.x ||
                       e.position.y < bounds.lo.y || e.position.y > bounds.hi.y))
      throw ScenarioError(grain + " is outside the container (x in [" +
                          std::to_string(bounds.lo.x) + ", " + std::to_string(bounds.hi.x) +
                          "], y in [" + std::to_string(bounds.lo.y) + ", " +
                          std::to_string(bounds.hi.y) + "] m)");
    for (std::size_t j = 0; j < w.walls.size(); ++j) {
      const Segment& seg = w.walls[j];
      const double overlap = e.radius - norm(e.position - closest_point(seg, e.position));
      if (overlap > 0.01 * e.radius)
        throw ScenarioError(grain + " overlaps wall segment " + std::to_string(j) + " by " +
                            std::to_string(overlap) +
                            " m at the start; allowed: at most 1% of "
                            "its radius");
    }
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.kind[i] == Kind::free) continue;
      const double overlap = e.radius + p.radius[i] - norm(e.position - p.position[i]);
      if (overlap > 0.01 * std::min(e.radius, p.radius[i]))
        throw ScenarioError(grain + " overlaps wall particle " + std::to_string(i) + " by " +
                            std::to_string(overlap) +
                            " m at the start; allowed: at most 1% of the smaller radius (move "
                            "the grain, or set geometry.wall_particle_radius)");
    }
  }
}

} // namespace talus
