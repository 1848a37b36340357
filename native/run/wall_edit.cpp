#include "run/wall_edit.hpp"

#include <algorithm>
#include <limits>

#include <fmt/core.h>

#include "scenario/build.hpp"
#include "scenario/file/load.hpp"
#include "scenario/geometry.hpp"

namespace talus::run {

namespace {

// The key a change of walls comes from, for messages.
const char* key_of(const Scenario& before, const Scenario& after) {
  return before.geometry.gate != after.geometry.gate ? "geometry.gate" : "geometry.segments";
}

// The walls of one group after the change, matched to those before by their place in the
// geometry: a wall given in both stays (moved as its drivers moved it), one given only after is
// added, one given only before is removed.
void match_group(const std::vector<SegmentSpec>& before, const std::vector<SegmentSpec>& after,
                 const std::vector<std::uint32_t>& world, std::uint16_t material, WallEdit& e,
                 std::vector<std::int64_t>& out) {
  std::vector<bool> taken(before.size(), false);
  for (const SegmentSpec& a : after) {
    std::size_t j = 0;
    while (j < before.size() && (taken[j] || !(before[j] == a))) ++j;
    if (j < before.size()) {
      taken[j] = true;
      out.push_back(world[j]);
      continue;
    }
    out.push_back(-1 - static_cast<std::int64_t>(e.added.size()));
    e.added.push_back(Segment{a.a, a.b, material});
  }
  for (std::size_t j = 0; j < before.size(); ++j)
    if (!taken[j]) e.removed[world[j]] = true;
}

// A driver's wall group may neither lose walls (a driven wall cannot vanish from under its
// motion) nor gain them (they would stand still while the rest moves).
void check_drivers(const Scenario& before, const Scenario& after, const WallEdit& e,
                   const std::map<std::string, DriverTargets>& groups) {
  for (const DriverSection& d : all_drivers(after)) {
    const auto old = groups.find(d.target);
    const auto now = e.groups.find(d.target);
    const bool same = d.target == "walls"
                          ? !e.any()
                          : old != groups.end() && now != e.groups.end() &&
                                std::equal(old->second.segments.begin(), old->second.segments.end(),
                                           now->second.begin(), now->second.end());
    if (!same)
      throw ScenarioError(fmt::format(
          "key '{}': the change takes walls from or adds walls to the group '{}', which a driver "
          "({}) moves; allowed: changes of undriven groups' walls",
          key_of(before, after), d.target, d.type));
  }
}

void check_stage_groups(const Scenario& after, const WallEdit& e, std::size_t first_stage) {
  for (std::size_t k = first_stage; k < after.stages.size(); ++k) {
    const std::string& g = after.stages[k].group;
    if (!g.empty() && !e.groups.count(g))
      throw ScenarioError(fmt::format("key 'stages.{}.group': the change removes wall group '{}', "
                                      "which this stage's condition ({}) looks at",
                                      k, g, after.stages[k].until));
  }
}

// An added wall may not cut into a grain: it would start at an overlap no timestep resolves.
void check_clear_of_grains(const Scenario& before, const Scenario& after, const World& w,
                           const Segments& added) {
  const Particles& p = w.particles;
  for (const Segment& s : added)
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!p.is_free(i) || norm(p.position[i] - closest_point(s, p.position[i])) >= p.radius[i])
        continue;
      throw ScenarioError(fmt::format(
          "key '{}': the wall added from ({:.6g}, {:.6g}) to ({:.6g}, {:.6g}) m cuts into grain "
          "{} at ({:.6g}, {:.6g}) m, radius {:.6g} m; walls can be added only clear of the grains",
          key_of(before, after), s.a.x, s.a.y, s.b.x, s.b.y, p.id[i], p.position[i].x,
          p.position[i].y, p.radius[i]));
    }
}

// Added ends a rounding step from a wall's end (one already there, or one added before) are
// made that end, as the build joins the container's walls; the walls already there stay put.
void join_added_ends(const World& w, Segments& added) {
  double r_min = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < w.particles.size(); ++i)
    if (w.particles.is_free(i)) r_min = std::min(r_min, w.particles.radius[i]);
  if (r_min == std::numeric_limits<double>::max()) return;
  Segments all = w.walls;
  all.insert(all.end(), added.begin(), added.end());
  join_segment_ends(all, wall_joint_tolerance * r_min);
  std::copy(all.end() - static_cast<std::ptrdiff_t>(added.size()), all.end(), added.begin());
}

} // namespace

WallEdit wall_edit(const Scenario& before, const Scenario& after, const World& w,
                   const std::map<std::string, DriverTargets>& groups, std::size_t first_stage) {
  WallEdit e;
  e.removed.assign(w.walls.size(), false);
  const ContainerShape was = build_container(before.geometry);
  const ContainerShape now = build_container(after.geometry);
  if (was.groups == now.groups) return e;
  if (before.geometry.walls == "particles")
    throw ScenarioError(fmt::format(
        "key '{}': walls made of particles (geometry.walls = \"particles\") cannot be added or "
        "removed during a run; allowed: segment walls (geometry.walls = \"segments\")",
        key_of(before, after)));
  const std::uint16_t material =
      material_index(after, after.geometry.wall_material, "geometry.wall_material");
  std::vector<std::string> names;
  for (const auto& [name, _] : was.groups) names.push_back(name);
  for (const auto& [name, _] : now.groups) names.push_back(name);
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  static const std::vector<SegmentSpec> none;
  for (const std::string& g : names) {
    if (g == "walls") continue; // their union, made below
    const auto b = was.groups.find(g), a = now.groups.find(g);
    const auto world = groups.find(g);
    std::vector<std::int64_t> out;
    match_group(b == was.groups.end() ? none : b->second, a == now.groups.end() ? none : a->second,
                world == groups.end() ? std::vector<std::uint32_t>{} : world->second.segments,
                material, e, out);
    if (!out.empty()) e.groups[g] = std::move(out);
  }
  std::vector<std::int64_t>& all = e.groups["walls"];
  if (const auto old = groups.find("walls"); old != groups.end())
    for (const std::uint32_t k : old->second.segments)
      if (!e.removed[k]) all.push_back(k);
  for (std::size_t k = 0; k < e.added.size(); ++k) all.push_back(-1 - static_cast<std::int64_t>(k));
  if (all.empty()) e.groups.erase("walls");
  check_drivers(before, after, e, groups);
  check_stage_groups(after, e, first_stage);
  join_added_ends(w, e.added);
  check_clear_of_grains(before, after, w, e.added);
  return e;
}

std::vector<std::int64_t> apply_wall_edit(Simulation& sim, const WallEdit& e,
                                          std::map<std::string, DriverTargets>& groups) {
  const std::vector<std::int64_t> to = sim.change_walls(e.removed, e.added);
  const auto kept =
      static_cast<std::int64_t>(std::count(e.removed.begin(), e.removed.end(), false));
  // the wall particles stay in their groups, those of particles alone ("fixed") too: a wall
  // edit changes segments only
  std::map<std::string, DriverTargets> next;
  for (const auto& [name, old] : groups)
    if (!old.particles.empty()) next[name].particles = old.particles;
  for (const auto& [name, walls] : e.groups) {
    DriverTargets& g = next[name];
    for (const std::int64_t k : walls)
      g.segments.push_back(static_cast<std::uint32_t>(k >= 0 ? to[k] : kept + (-1 - k)));
  }
  groups = std::move(next);
  return to;
}

} // namespace talus::run
