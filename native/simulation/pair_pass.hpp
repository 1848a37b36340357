#pragma once
// The pair pass of the force stage: the forces of the touching entries of a stretch of rows, two
// at a time (one per SIMD lane), from the laws in src/talus, added to both partners in entry
// order. A partner beyond the block gets its share later, from the entry's deferred slot.
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "core/contact_lanes.hpp"
#include "materials/pair_table.hpp"
#include "simulation/block_arrays.hpp"

namespace talus {

/// The pair parameters of two contacts, in lanes. In a scene of one material (`material`, when
/// one_material) every contact has the same ones: they are put in lanes once, not for every two
/// contacts.
class PairLaneSource {
public:
  PairLaneSource(const PairTable& pairs, bool one_material, std::uint16_t material)
      : pairs_(pairs),
        uniform_(one_material ? pair_lanes(pairs(material, material), pairs(material, material))
                              : pair_lanes(PairParameters{}, PairParameters{})) {}
  const PairLanes& uniform_lanes() const { return uniform_; }
  PairLanes lanes(std::uint16_t mi0, std::uint16_t mj0, std::uint16_t mi1,
                  std::uint16_t mj1) const {
    return pair_lanes(pairs_(mi0, mj0), pairs_(mi1, mj1));
  }

private:
  const PairTable& pairs_;
  PairLanes uniform_;
};

/// The forces of found[0, count) (touching entries of the stretch from row r0), c0 in lane 0 and
/// c1 in lane 1; an odd last contact fills both lanes, in a step of shape S (step_features.hpp),
/// with the lever arms short of the radii by `shares` of the overlap.
/// Returns the largest overlap / smaller radius. `Sliding`: the domain's Lees-Edwards images move
/// (Domain::shear_velocity), which a partner across y then has in its velocity; a step without
/// them is compiled without the test.
template <class N, class T, class S, bool Sliding>
[[gnu::always_inline]] inline double pair_forces(const BlockArrays& a, const PairLaneSource& pairs,
                                                 const TouchingEntry* found, std::size_t count,
                                                 std::ptrdiff_t r0, double dt, LeverShares shares) {
  double worst = 0.0;
  for (std::size_t t = 0; t < count; t += 2) {
    const TouchingEntry& c0 = found[t];
    const bool two = t + 1 < count;
    const TouchingEntry& c1 = found[two ? t + 1 : t];
    // the entries' particles, from the list (the stretch's entries are in the L1 cache)
    const auto i0 = static_cast<std::uint32_t>(r0 + a.row_in_stretch[c0.entry]);
    const auto i1 = static_cast<std::uint32_t>(r0 + a.row_in_stretch[c1.entry]);
    const std::uint32_t j0 = a.neighbour[c0.entry], j1 = a.neighbour[c1.entry];
    const Lanes ri{a.radius[i0], a.radius[i1]}, rj{a.radius[j0], a.radius[j1]};
    const Lanes dx{c0.d.x, c1.d.x}, dy{c0.d.y, c1.d.y};
    // without rotation every angular velocity is 0: nothing to load
    const Lanes wi = S::rotation ? Lanes{a.spin[i0], a.spin[i1]} : Lanes{};
    const Lanes wj = S::rotation ? Lanes{a.spin[j0], a.spin[j1]} : Lanes{};
    Lanes vjx{a.velocity[j0].x, a.velocity[j1].x};
    if constexpr (Sliding) { // j's image across a Lees-Edwards side
      const double u = a.shear_velocity;
      vjx += Lanes{a.images[c0.entry].sy * u, a.images[c1.entry].sy * u};
    }
    const ContactLanes g = pair_geometry(
        dx, dy, square_root(dx * dx + dy * dy), ri, rj, Lanes{a.mass[i0], a.mass[i1]},
        Lanes{a.mass[j0], a.mass[j1]}, Lanes{a.velocity[i0].x, a.velocity[i1].x},
        Lanes{a.velocity[i0].y, a.velocity[i1].y}, vjx, Lanes{a.velocity[j0].y, a.velocity[j1].y},
        wi, wj, N::uses_r_eff || T::uses_r_eff, shares);
    // a law without history neither reads nor changes the springs: not loaded, not stored
    Lanes spring{};
    if constexpr (T::has_history) spring = Lanes{a.history[c0.entry], a.history[c1.entry]};
    ForceLanes f;
    if constexpr (S::one_material)
      f = contact_force<N, T>(pairs.uniform_lanes(), g, spring, dt);
    else
      f = contact_force<N, T>(
          pairs.lanes(a.material[i0], a.material[j0], a.material[i1], a.material[j1]), g, spring,
          dt);
    const auto add = [&](const TouchingEntry& c, std::uint32_t i, std::uint32_t j, int lane) {
      const Vec2 force{f.force_x[lane], f.force_y[lane]};
      if constexpr (T::has_history) a.history[c.entry] = spring[lane];
      a.p.force[i] += force;
      if constexpr (S::rotation) a.p.torque[i] += f.torque_i[lane];
      if (c.slot != no_slot) [[unlikely]] {
        a.slots[c.slot].force = force;
        if constexpr (S::rotation) {
          a.slots[c.slot].torque_i = f.torque_i[lane];
          a.slots[c.slot].torque_j = f.torque_j[lane];
        }
      } else {
        a.p.force[j] -= force;
        if constexpr (S::rotation) a.p.torque[j] += f.torque_j[lane];
      }
    };
    add(c0, i0, j0, 0);
    if (two) add(c1, i1, j1, 1);
    const Lanes ratio = g.overlap / smaller(ri, rj);
    worst = std::max(worst, std::max(ratio[0], ratio[1]));
  }
  return worst;
}

} // namespace talus
