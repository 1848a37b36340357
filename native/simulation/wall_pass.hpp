#pragma once
// The wall pass of the force stage: the contacts of particles with wall segments, found from the
// particles' wall rows of the neighbour list. One definition of a wall contact
// (for_each_wall_contact), for the force stage and for the observers
// (Simulation::for_each_contact).
#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/contact_vectors.hpp"
#include "materials/pair_table.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"
#include "state/walls.hpp"
#include "talus/contact_force.hpp"
#include "talus/segment_contact.hpp"

namespace talus {

// The wall geometry is src/talus/segment_contact.hpp's, shared with the LAMMPS package.
using WallHit = SegmentHit;

inline WallHit wall_hit(const Segment& s, Vec2 p, double radius) {
  return segment_hit(s.a.x, s.a.y, s.b.x, s.b.y, p.x, p.y, radius);
}

// Calls touching(e, segment, geometry) for each entry e of particle i's wall row whose segment i
// touches (the shared end point of two segments once), and apart(e) for the others. `hits` is
// scratch space, kept by the caller so that a step allocates nothing.
template <class Touching, class Apart>
void for_each_wall_contact(const Particles& p, const NeighbourList& list, const Segments& walls,
                           std::uint32_t i, std::vector<WallHit>& hits, LeverShares shares,
                           Touching&& touching, Apart&& apart) {
  const std::uint32_t w0 = list.wall_offset[i], w1 = list.wall_offset[i + 1];
  if (w0 == w1) return;
  const Vec2 ri = p.position[i];
  const double Ri = p.radius[i];
  hits.clear();
  for (std::uint32_t e = w0; e < w1; ++e)
    hits.push_back(wall_hit(walls[list.wall_segment[e]], ri, Ri));
  for (std::uint32_t e = w0; e < w1; ++e) {
    const WallHit& h = hits[e - w0];
    const auto has_end = [&](std::size_t m, double x, double y) {
      const Segment& o = walls[list.wall_segment[w0 + m]];
      return (o.a.x == x && o.a.y == y) || (o.b.x == x && o.b.y == y);
    };
    if (!h.touching || (h.vertex() && duplicate_vertex(hits, hits.size(), e - w0, has_end))) {
      apart(e);
      continue;
    }
    const Segment& s = walls[list.wall_segment[e]];
    const Vec2 d = ri - Vec2{h.x, h.y};
    touching(e, s,
             wall_geometry(d, norm(d), Ri, p.mass[i], p.velocity[i], p.angular_velocity[i],
                           s.velocity_at(Vec2{h.x, h.y}), shares));
  }
}

// The wall contacts of late particle i (particles with wall contacts are late): their forces into
// `out`, one per entry of its wall row (0 if not touching), in a step of shape S
// (step_features.hpp; `uniform`: the one material's pair, when S::one_material); returns the
// largest overlap / radius. Not inlined into the stage (its loops are compiled worse with more
// code in them).
template <class N, class T, class S>
[[gnu::noinline]] double
wall_contacts(const Particles& p, NeighbourList& list, const Segments& walls,
              const PairTable& pairs, const PairParameters& uniform, std::vector<PairForce>& out,
              double dt, LeverShares shares, std::uint32_t i, std::vector<WallHit>& hits) {
  double worst = 0.0;
  for_each_wall_contact(
      p, list, walls, i, hits, shares,
      [&](std::uint32_t e, const Segment& s, const ContactGeometry& g) {
        double none = 0.0; // the spring of a list that keeps none
        double& spring = S::history ? list.wall_history[e] : none;
        out[e] = contact_force<N, T>(S::one_material ? uniform : pairs(p.material[i], s.material),
                                     g, spring, dt);
        worst = std::max(worst, g.overlap / p.radius[i]);
      },
      [&](std::uint32_t e) {
        out[e] = {};
        if constexpr (S::history) list.wall_history[e] = 0.0;
      });
  return worst;
}

// The walls' reactions, particle by particle: the wall rows in order (a particle's wall entries
// follow those of the particles before it).
inline void sum_wall_reactions(const NeighbourList& list, const std::vector<PairForce>& wf,
                               Segments& walls) {
  for (Segment& s : walls) s.force = {};
  for (std::size_t e = 0; e < list.wall_segment.size(); ++e)
    walls[list.wall_segment[e]].force -= wf[e].force;
}

} // namespace talus
