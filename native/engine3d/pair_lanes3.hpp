#pragma once
// The pair contacts of a block of rows of the sphere list, two at a time (one per SIMD lane,
// core/lanes.hpp), from the laws of src/talus in 3D: first the touch test writes down the
// touching entries without a branch per entry, then their forces are computed side by side and
// added to both spheres in entry order, or, for a second sphere beyond the block, kept in the
// entry's deferred force. Each lane rounds as the double code does, so the results are the
// scalar ones to the bit.
#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/lanes.hpp"
#if defined(__AVX2__)
#include "core/lanes4.hpp"
#endif
#include "core/vec3.hpp"
#include "engine3d/force_pass3.hpp"
#include "engine3d/rolling3.hpp"
#include "engine3d/scene3.hpp"
#include "engine3d/sphere_list.hpp"
#include "materials/pair_table.hpp"
#include "talus/contact_force.hpp"
#include "talus/contact_geometry_3d.hpp"
#include "talus/rolling_resistance.hpp"

namespace talus {

/// The lanes the 3D pair contacts are computed in: four in a build with AVX2, else two (SSE2).
#if defined(__AVX2__)
using ContactLanes3 = Lanes4;
#else
using ContactLanes3 = Lanes;
#endif

/// The number of lanes of a SIMD type of doubles.
template <class L> inline constexpr int lane_count = static_cast<int>(sizeof(L) / sizeof(double));

/// Lanes whose lane k is f(k). Built as one initialiser, so that the values go to the register
/// directly, not through memory.
template <class L, class F> L lanes_from(F&& f) {
  if constexpr (lane_count<L> == 2) {
    return L{f(0), f(1)};
  } else {
    static_assert(lane_count<L> == 4);
    return L{f(0), f(1), f(2), f(3)};
  }
}
/// Vectors of lanes whose lane k is the vector f(k).
template <class L, class F> Vec3Of<L> vec3_lanes_from(F&& f) {
  if constexpr (lane_count<L> == 2) {
    const Vec3 a = f(0), b = f(1);
    return {L{a.x, b.x}, L{a.y, b.y}, L{a.z, b.z}};
  } else {
    static_assert(lane_count<L> == 4);
    const Vec3 a = f(0), b = f(1), c = f(2), d = f(3);
    return {L{a.x, b.x, c.x, d.x}, L{a.y, b.y, c.y, d.y}, L{a.z, b.z, c.z, d.z}};
  }
}
template <class L> Vec3 lane_of(const Vec3Of<L>& v, int k) {
  return {v.x[k], v.y[k], v.z[k]};
}
/// One lane of a contact's geometry, as the double code has it.
template <class L> ContactGeometry3 lane_of(const ContactGeometry3Of<L>& g, int k) {
  return {lane_of(g.normal, k), g.overlap[k], g.r_eff[k],    g.m_eff[k],
          g.arm_i[k],           g.arm_j[k],   g.v_normal[k], lane_of(g.v_tangent, k)};
}

/// Where a block's pair forces go: its spheres [first, last) sum theirs directly; an entry whose
/// second sphere lies beyond `last` keeps its force and j's torque (deferred_*) for later.
struct BlockSums3 {
  Spheres& s;
  std::uint32_t first, last;
  Vec3* deferred_force;
  Vec3* deferred_torque_j;
  double slide = 0.0; ///< m/s: the Lees-Edwards images' velocity along x (Domain3::shear_velocity)
};

/// Tests every entry of rows [r0, r1) of the block: a touching one is written down in `found`
/// (which has room for every entry of the rows). `touched[e]` says whether entry e touched at the
/// last pass: an entry that touched then and does not now has its spring cleared (where the list
/// keeps springs, `Springs`; its rolling spring, `Rolling`; and its deferred force). Those of an
/// entry that did not touch are 0 already, so that only the contacts that end cost a write. Returns
/// the count written. The arrays are taken as pointers once: the loop has more of them than
/// registers.
template <bool Springs, bool Rolling>
std::size_t touching_entries(const Spheres& s, SphereList& list, const Domain3& domain,
                             const BlockSums3& b, std::uint32_t r0, std::uint32_t r1,
                             std::uint8_t* touched, Touching3* found) {
  const Vec3* const position = s.position.data();
  const double* const radius = s.radius.data();
  const std::uint32_t* const row_offset = list.row_offset.data();
  const std::uint32_t* const neighbour = list.neighbour.data();
  const Shift3* const shift = list.shift.data();
  Vec3* const spring = list.spring.data();
  Vec3* const rolling = list.rolling.data();
  std::size_t count = 0;
  for (std::uint32_t i = r0; i < r1; ++i) {
    const Vec3 ri = position[i];
    const double radius_i = radius[i];
    const std::uint32_t end = row_offset[i + 1];
    for (std::uint32_t e = row_offset[i]; e < end; ++e) {
      const std::uint32_t j = neighbour[e];
      Vec3 rj = position[j];
      const Shift3 image = shift[e];
      if (image.x != 0 || image.y != 0 || image.z != 0) [[unlikely]] // a periodic image
        rj += domain.image_shift(image.x, image.y, image.z);
      const Vec3 d = ri - rj;
      const double dist2 = norm2(d);
      const double reach = radius_i + radius[j];
      // "not beyond reach" rather than "within reach": a NaN distance counts as touching, so
      // that it reaches the forces and the stability guard
      const bool touches = !(dist2 >= reach * reach) & (dist2 != 0.0);
      // which entries touch follows no pattern a branch predictor could learn: no branch on it
      found[count] = {d, e, i};
      count += touches;
      // but few contacts end in a step
      if (touched[e] > static_cast<std::uint8_t>(touches)) [[unlikely]] {
        if constexpr (Springs) spring[e] = {};
        if constexpr (Rolling) rolling[e] = {};
        if (j >= b.last) b.deferred_force[e] = b.deferred_torque_j[e] = {};
      }
      touched[e] = static_cast<std::uint8_t>(touches);
    }
  }
  return count;
}

/// Sphere i's spin, or 0 in a step without rotation (which the laws then need not look up).
template <bool Rotation> Vec3 spin_of(const Spheres& s, std::uint32_t i) {
  if constexpr (Rotation) return s.angular_velocity[i];
  return {};
}

/// The parameters *p[k] of lane k's pair, in lanes L.
template <class L>
PairParametersOf<L> parameters_in_lanes(const std::array<const PairParameters*, lane_count<L>>& p) {
  const auto two = [](double x, double y) { return Lanes{x, y}; };
  if constexpr (lane_count<L> == 2) {
    return PairParametersOf<Lanes>::gather(*p[0], *p[1], two);
  } else {
    static_assert(lane_count<L> == 4);
    return PairParametersOf<L>::gather(PairParametersOf<Lanes>::gather(*p[0], *p[1], two),
                                       PairParametersOf<Lanes>::gather(*p[2], *p[3], two),
                                       [](Lanes x, Lanes y) {
                                         return L{x[0], x[1], y[0], y[1]};
                                       });
  }
}

/// The pair parameters of contacts side by side, in lanes L: once for a scene of one material
/// (where `once` allows it), else looked up per contact.
template <class L> class PairLanes3 {
public:
  explicit PairLanes3(const PairTable& table, bool once = true)
      : table_(table), one_(once && table.material_count() == 1) {
    if (one_) uniform_ = broadcast(table(0, 0));
  }
  /// The parameters of the pairs (i[k], j[k]) in lane k.
  PairParametersOf<L> operator()(const Spheres& s, const std::uint32_t* i,
                                 const std::uint32_t* j) const {
    if (one_) return uniform_;
    std::array<const PairParameters*, lane_count<L>> pair;
    for (int k = 0; k < lane_count<L>; ++k)
      pair[static_cast<std::size_t>(k)] = &table_(s.material[i[k]], s.material[j[k]]);
    return parameters_in_lanes<L>(pair);
  }

private:
  static PairParametersOf<L> broadcast(const PairParameters& p) {
    return PairParametersOf<L>::gather(p, p, [](double x, double) { return L{} + x; });
  }
  const PairTable& table_;
  bool one_;
  PairParametersOf<L> uniform_{};
};

/// The forces of found[0, count), as many at a time as L has lanes (the last ones repeated to
/// fill them), added in entry order: to i, and to j or the entry's deferred force. Without
/// `Rotation` the spins are taken as 0 and no torque is added.
template <class N, class T, bool Rotation, class L>
[[gnu::flatten]] ContactTally3 pair_forces3(const BlockSums3& b, SphereList& list,
                                            const PairLanes3<L>& pairs, const PairTable& table,
                                            const Touching3* found, std::size_t count, double dt,
                                            LeverShares shares) {
  constexpr int width = lane_count<L>;
  Spheres& s = b.s;
  ContactTally3 tally;
  for (std::size_t t = 0; t < count; t += width) {
    const int live = static_cast<int>(std::min<std::size_t>(width, count - t));
    std::uint32_t entry[width], i[width], j[width];
    for (int k = 0; k < width; ++k) {
      const Touching3& c = found[t + static_cast<std::size_t>(std::min(k, live - 1))];
      entry[k] = c.entry, i[k] = c.i, j[k] = list.neighbour[c.entry];
    }
    const auto each = [&](const auto& field) { return [&](int k) { return field[i[k]]; }; };
    const auto each_j = [&](const auto& field) { return [&](int k) { return field[j[k]]; }; };
    const L ri = lanes_from<L>(each(s.radius)), rj = lanes_from<L>(each_j(s.radius));
    const Vec3Of<L> d = vec3_lanes_from<L>(
        [&](int k) { return found[t + static_cast<std::size_t>(std::min(k, live - 1))].d; });
    Vec3Of<L> v_j = vec3_lanes_from<L>(each_j(s.velocity));
    if (b.slide != 0.0) [[unlikely]] // Lees-Edwards images slide: once for the lanes
      v_j.x += lanes_from<L>([&](int k) { return list.shift[entry[k]].y * b.slide; });
    const ContactGeometry3Of<L> g =
        pair_geometry(d, square_root(dot(d, d)), ri, rj, lanes_from<L>(each(s.mass)),
                      lanes_from<L>(each_j(s.mass)), vec3_lanes_from<L>(each(s.velocity)), v_j,
                      vec3_lanes_from<L>([&](int k) { return spin_of<Rotation>(s, i[k]); }),
                      vec3_lanes_from<L>([&](int k) { return spin_of<Rotation>(s, j[k]); }),
                      N::uses_r_eff || T::uses_r_eff || list.with_rolling, shares);
    Vec3Of<L> spring{};
    if constexpr (T::has_history)
      spring = vec3_lanes_from<L>([&](int k) { return list.spring[entry[k]]; });
    const ContactForce3Of<L> f = contact_force<N, T>(pairs(s, i, j), g, spring, dt);
    for (int k = 0; k < live; ++k) {
      const Vec3 force = lane_of(f.force, k);
      Vec3 torque_i = lane_of(f.torque_i, k), torque_j = lane_of(f.torque_j, k);
      if constexpr (T::has_history) list.spring[entry[k]] = lane_of(spring, k);
      if (Rotation && list.with_rolling) {
        const Vec3 m =
            rolling_torque<N>(table(s.material[i[k]], s.material[j[k]]), lane_of(g, k),
                              f.normal_force[k], s.angular_velocity[i[k]], s.angular_velocity[j[k]],
                              rim_of(s, i[k]), rim_of(s, j[k]), list.rolling[entry[k]], dt);
        torque_i += m, torque_j -= m;
      }
      s.force[i[k]] += force;
      if constexpr (Rotation) s.torque[i[k]] += torque_i;
      if (j[k] < b.last) {
        s.force[j[k]] -= force;
        if constexpr (Rotation) s.torque[j[k]] += torque_j;
      } else {
        b.deferred_force[entry[k]] = force;
        if constexpr (Rotation) b.deferred_torque_j[entry[k]] = torque_j;
      }
    }
    const L ratio = g.overlap / smaller(ri, rj);
    for (int k = 0; k < live; ++k) tally.deepest = std::max(tally.deepest, ratio[k]);
    tally.contacts += static_cast<std::size_t>(live);
  }
  return tally;
}

} // namespace talus
