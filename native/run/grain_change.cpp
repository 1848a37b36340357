// Grains added and removed during a run (Run::add_grains, remove_grains): checked as a
// scenario's grains are, recorded in changes.csv, and followed by the run's own indices (tracked
// grains, wall groups) and by its observers (the energy ledger).
#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include <fmt/core.h>

#include "analysis/observables.hpp"
#include "run/run.hpp"
#include "scenario/file/load.hpp"
#include "scenario/file/toml_reader.hpp"

namespace talus::run {

namespace {

bool finite(Vec2 v) {
  return std::isfinite(v.x) && std::isfinite(v.y);
}

// The first thing that keeps grain k (`g`) out of the run, or empty.
std::string grain_problem(const Scenario& s, const Simulation& sim, const ParticleSpec& g,
                          const std::vector<ParticleSpec>& before) {
  const World& w = sim.world();
  if (!finite(g.position) || !finite(g.velocity) || !std::isfinite(g.angular_velocity))
    return "its position, velocity and spin must be finite numbers";
  if (!(g.radius > 0.0) || !std::isfinite(g.radius))
    return fmt::format("radius {}; allowed: a finite radius > 0 m", g.radius);
  if (g.material >= s.materials.size())
    return fmt::format("material {}; allowed: 0 to {} (the scenario's materials)", g.material,
                       s.materials.size() - 1);
  if (g.kind != Kind::free) return "only free grains can be added";
  const SimulationConfig& c = sim.config();
  if (c.escape_hi.x > c.escape_lo.x &&
      (g.position.x < c.escape_lo.x || g.position.y < c.escape_lo.y ||
       g.position.x > c.escape_hi.x || g.position.y > c.escape_hi.y))
    return fmt::format("({:.6g}, {:.6g}) m is outside the region the run's grains may be in, "
                       "[{:.6g}, {:.6g}] x [{:.6g}, {:.6g}] m",
                       g.position.x, g.position.y, c.escape_lo.x, c.escape_hi.x, c.escape_lo.y,
                       c.escape_hi.y);
  const Particles& p = w.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (norm(w.domain.minimum_image(g.position, p.position[i])) < g.radius + p.radius[i])
      return fmt::format("it overlaps particle id {} at ({:.6g}, {:.6g}) m", p.id[i],
                         p.position[i].x, p.position[i].y);
  for (std::size_t k = 0; k < before.size(); ++k)
    if (norm(w.domain.minimum_image(g.position, before[k].position)) < g.radius + before[k].radius)
      return fmt::format("it overlaps the grain added before it, number {}", k);
  for (std::size_t k = 0; k < w.walls.size(); ++k)
    if (norm(g.position - closest_point(w.walls[k], g.position)) < g.radius)
      return fmt::format("it overlaps wall segment {}", k);
  return {};
}

} // namespace

void Run::record_grain_change(const std::string& what, const std::string& source,
                              double energy_before) {
  WorldChange done;
  done.energy_before = energy_before;
  for (auto& o : observers_) o->changed(c_, done);
  log_change(source, what);
}

std::vector<std::uint32_t> Run::add_grains(std::vector<ParticleSpec> grains,
                                           const std::string& source) {
  if (s_.frost.model != "none")
    throw ScenarioError("grains cannot be added to a run with a frost model (frost.model = '" +
                        s_.frost.model + "'), which keeps the grains it holds by index");
  for (std::size_t k = 0; k < grains.size(); ++k) {
    ParticleSpec& g = grains[k];
    const std::vector<ParticleSpec> before(grains.begin(), grains.begin() + k);
    if (const std::string why = grain_problem(s_, sim_, g, before); !why.empty())
      throw ScenarioError(fmt::format("grain {} to add: {}", k, why));
    if (g.mass == 0.0)
      g.mass = shape_mass(s_.particles.shape, g.radius, s_.materials[g.material].density);
    if (g.inertia == 0.0) g.inertia = shape_inertia(s_.particles.shape, g.mass, g.radius);
  }
  if (grains.empty()) return {};
  const double energy_before = energies(sim_).total();
  const std::size_t first = sim_.add_particles(grains);
  std::vector<std::uint32_t> ids;
  for (std::size_t i = first; i < sim_.world().particles.size(); ++i)
    ids.push_back(sim_.world().particles.id[i]);
  record_grain_change(
      fmt::format("add {} grains: ids {} to {}", ids.size(), ids.front(), ids.back()), source,
      energy_before);
  return ids;
}

void Run::remove_grains(const std::vector<std::uint32_t>& ids, const std::string& source) {
  if (s_.frost.model != "none")
    throw ScenarioError("grains cannot be removed from a run with a frost model (frost.model = '" +
                        s_.frost.model + "'), which keeps the grains it holds by index");
  const Particles& p = sim_.world().particles;
  std::unordered_map<std::uint32_t, std::size_t> index_of;
  for (std::size_t i = 0; i < p.size(); ++i) index_of[p.id[i]] = i;
  std::vector<bool> removed(p.size(), false);
  std::string listed;
  for (const std::uint32_t id : ids) {
    const auto at = index_of.find(id);
    if (at == index_of.end())
      throw ScenarioError(fmt::format("grain id {} to remove: no such grain", id));
    const std::size_t i = at->second;
    if (p.kind[i] != Kind::free)
      throw ScenarioError(fmt::format("grain id {} to remove: a wall or held particle; only free "
                                      "grains can be removed",
                                      id));
    if (std::find(book_.tracked.begin(), book_.tracked.end(), i) != book_.tracked.end())
      throw ScenarioError(fmt::format("grain id {} to remove: it is tracked (track.csv follows "
                                      "it)",
                                      id));
    if (!removed[i]) {
      if (!listed.empty()) listed += ' ';
      listed += std::to_string(id);
    }
    removed[i] = true;
  }
  if (ids.empty()) return;
  const double energy_before = energies(sim_).total();
  const std::vector<std::int64_t> to = sim_.remove_particles(removed);
  for (std::uint32_t& i : book_.tracked) i = static_cast<std::uint32_t>(to[i]);
  for (auto& [name, g] : book_.groups)
    for (std::uint32_t& i : g.particles) i = static_cast<std::uint32_t>(to[i]);
  record_grain_change(fmt::format("remove {} grains: ids {}",
                                  std::count(removed.begin(), removed.end(), true), listed),
                      source, energy_before);
}

} // namespace talus::run
