#pragma once
// The late pass of the force stage: the late particles (NeighbourList::late), whose force is
// complete only once every block and every wall contact is done, get their deferred pair forces
// and their wall forces, then the finishing policy (particle_finish.hpp).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/contact_vectors.hpp"
#include "integrate/integrator.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"

namespace talus {

// Late particles per chunk that a thread takes at a time in the wall contacts and the late pass: a
// particle's sums are its own, so which thread takes a chunk changes no result. Chunks taken one at
// a time, not an equal split: the wall contacts gather in a few places (a floor's particles come
// first), which an equal split gives to one thread.
inline constexpr int late_chunk = 256;

// The late particles late[q0, q1): each adds, in a fixed order, its deferred pair forces (in
// entry order), then its wall contacts; then they are done, by runs of consecutive particles (a
// layer of a packing at a block's start is late, so runs are long: `done` takes two at a time
// there, where it took them one by one). Without Rotation no torque is summed.
template <bool Rotation, class Done>
[[gnu::noinline]] PassReport
finish_late(Particles& p, const NeighbourList& list, const std::vector<PairForce>& deferred,
            const std::vector<PairForce>& wf, const Done& done, std::size_t q0, std::size_t q1) {
  for (std::size_t q = q0; q < q1; ++q) {
    const std::uint32_t k = list.late[q];
    for (std::uint32_t c = list.deferred_offset[k]; c < list.deferred_offset[k + 1]; ++c) {
      const PairForce& f = deferred[list.deferred_slot[c]];
      p.force[k] -= f.force;
      if constexpr (Rotation) p.torque[k] += f.torque_j;
    }
    for (std::uint32_t e = list.wall_offset[k]; e < list.wall_offset[k + 1]; ++e) {
      p.force[k] += wf[e].force;
      if constexpr (Rotation) p.torque[k] += wf[e].torque_i;
    }
  }
  PassReport seam{true, 0.0};
  for (std::size_t q = q0; q < q1;) {
    std::size_t r = q + 1;
    while (r < q1 && list.late[r] == list.late[r - 1] + 1) ++r;
    const PassReport s = done.range(list.late[q], list.late[r - 1] + std::size_t{1});
    seam.finite = seam.finite && s.finite;
    seam.displacement2 = std::max(seam.displacement2, s.displacement2);
    q = r;
  }
  return seam;
}

} // namespace talus
