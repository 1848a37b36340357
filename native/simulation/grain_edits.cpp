// Grains added and removed between steps (Simulation::add_particles, remove_particles): a silo
// filled as it empties, grains taken out of a region, an experiment scripted in Python.
#include <algorithm>
#include <string>

#include "simulation/simulation.hpp"
#include "talus/error.hpp"

namespace talus {

namespace {

// The list's rows, pairs' and walls', made `rows` long: rows added empty, rows past the end cut
// off. The next build carries the springs of a list with as many rows as particles, so the kept
// contacts keep theirs across an edit of the particles.
void resize_rows(NeighbourList& l, std::size_t rows) {
  for (std::vector<std::uint32_t>* offset : {&l.row_offset, &l.wall_offset}) {
    if (offset->empty()) continue;
    if (offset->size() > rows + 1)
      offset->resize(rows + 1);
    else
      offset->resize(rows + 1, offset->back());
  }
}

} // namespace

std::size_t Simulation::add_particles(const std::vector<ParticleSpec>& specs) {
  Particles& p = world_.particles;
  for (std::size_t k = 0; k < specs.size(); ++k) {
    const ParticleSpec& s = specs[k];
    const std::string which = "add_particles: particle " + std::to_string(k);
    if (s.material >= world_.materials.size())
      throw InvalidArgument(which + ": material " + std::to_string(s.material) +
                            " is not one of the " + std::to_string(world_.materials.size()) +
                            " materials");
    if (s.kind == Kind::moved)
      throw InvalidArgument(which + ": a moved particle is a driver's; allowed: free, fixed");
  }
  const std::size_t first = p.size();
  std::uint32_t next_id = 0;
  for (const std::uint32_t id : p.id) next_id = std::max(next_id, id + 1);
  // Particles::add starts Gear's history afresh for a new system: kept here, extended below
  GearDerivatives gear = std::move(p.gear);
  for (const ParticleSpec& s : specs) {
    const std::size_t i = p.add(s);
    p.id[i] = next_id++;
    const bool free = s.kind == Kind::free;
    const Vec2 a = free ? world_.gravity : Vec2{}; // free flight until the next forces
    p.force[i] = s.mass * a;
    if (!gear.empty()) {
      gear.r2.push_back(a), gear.r3.push_back({}), gear.r4.push_back({});
      gear.phi2.push_back(0.0), gear.phi3.push_back(0.0), gear.phi4.push_back(0.0);
    }
    if (!p.force_previous.empty()) p.force_previous.push_back(p.force[i]);
    if (!p.torque_previous.empty()) p.torque_previous.push_back(0.0);
  }
  p.gear = std::move(gear);
  // built now, not at the next step: what looks at the contacts in between (the ledger's energy,
  // Python's arrays) sees the particles as they are
  resize_rows(list_, p.size());
  rebuild_list(threads_);
  features_stale_ = true; // a new material or kind may be in the scene
  return first;
}

std::vector<std::int64_t> Simulation::remove_particles(const std::vector<bool>& removed) {
  Particles& p = world_.particles;
  const std::size_t n = p.size();
  if (removed.size() != n)
    throw InvalidArgument("remove_particles: " + std::to_string(removed.size()) + " flags for " +
                          std::to_string(n) + " particles");
  for (std::size_t i = 0; i < n; ++i)
    if (removed[i] && p.kind[i] != Kind::free)
      throw InvalidArgument("remove_particles: particle " + std::to_string(i) + " (id " +
                            std::to_string(p.id[i]) +
                            ") is a wall or held particle; only free grains can be removed");
  // the kept particles first, in their order, then the removed ones, which are cut off
  std::vector<std::uint32_t> order;
  order.reserve(n);
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t i = 0; i < n; ++i)
      if (removed[i] == (pass == 1)) order.push_back(static_cast<std::uint32_t>(i));
  const std::size_t kept =
      n - static_cast<std::size_t>(std::count(removed.begin(), removed.end(), true));
  std::vector<std::uint32_t> new_of_old(n);
  for (std::size_t k = 0; k < n; ++k) new_of_old[order[k]] = static_cast<std::uint32_t>(k);
  p.permute(order, threads_);
  // the list follows the renumbering, so that the rebuild finds the kept pairs' springs; the
  // entries of removed particles are never asked for again
  renumber_neighbour_list(list_, order, new_of_old, threads_);
  p.for_each_field([&](auto& v) {
    if (v.size() == n) v.resize(kept);
  });
  resize_rows(list_, kept);
  std::vector<std::int64_t> to(n, -1);
  for (std::size_t i = 0; i < n; ++i)
    if (!removed[i]) to[i] = new_of_old[i];
  for (Driver& d : world_.drivers)
    for (std::uint32_t& i : d.targets.particles) i = new_of_old[i];
  list_moved();
  rebuild_list(threads_); // the removed particles' entries go now (as in add_particles)
  features_stale_ = true;
  return to;
}

} // namespace talus
