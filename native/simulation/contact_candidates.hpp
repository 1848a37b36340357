#pragma once
// The touch test of the force stage: the first pass over a stretch of rows writes down the
// entries that touch, with masks instead of a branch per entry (in a disordered packing which
// neighbours touch follows no pattern a branch predictor can learn), and clears the history of
// the others. It tests only the contact candidates, the entries that may touch before the grains
// move on; when they are chosen again it tests every entry and writes them down. The touching
// entries found, and so the results, are the same either way.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "simulation/block_arrays.hpp"

namespace talus {

/// The entries of a neighbour list that can come to touch soon: those whose gap was below `skin`
/// when they were chosen, and those that name a particle that is not free (drivers and holds
/// move those, not the integrator). While no two grains can have closed a gap of `skin` since
/// then (ForceStage keeps the bound), the force stage tests only these: the others cannot touch,
/// and their history stays 0. Derived from the list by the force stage, not saved.
struct ContactCandidates {
  std::vector<std::uint32_t> entry; ///< per stretch of rows, from the stretch's first entry on
  std::vector<std::uint32_t> slot;  ///< each candidate's deferred slot, or no_slot
  std::vector<std::uint32_t> count; ///< candidates per stretch of rows
  double skin = 0.0;                ///< m
  /// `skin` as a fraction of the list's skin: they are chosen again about five times in a
  /// list's life; the choice is not sensitive (docs/performance.md, "Contact candidates").
  static constexpr double skin_fraction = 0.2;
};

/// What the touch test learns of an entry, for choosing the candidates.
struct EntryGap {
  double dist2, reach;
  std::uint32_t i, j;
};

/// Tests entry e of the stretch from row r0: if it touches, it is written down at found[count]
/// with its deferred slot `to` and counted; if not, its history is cleared (if the list keeps
/// one: History).
template <bool History>
[[gnu::always_inline]] inline EntryGap test_entry(const BlockArrays& a, std::ptrdiff_t r0,
                                                  std::uint32_t e, std::uint32_t to,
                                                  TouchingEntry* found, std::size_t& count) {
  const auto i = static_cast<std::uint32_t>(r0 + a.row_in_stretch[e]);
  const std::uint32_t j = a.neighbour[e];
  Vec2 rj = a.position[j];
  const ImageShift image = a.images[e];
  if (image.sx != 0 || image.sy != 0) [[unlikely]] // across a periodic boundary
    rj += Vec2{image.sx * a.box.x + image.sy * a.shear_offset, image.sy * a.box.y};
  const Vec2 d = a.position[i] - rj;
  const double dist2 = norm2(d);
  const double reach = a.radius[i] + a.radius[j];
  // "not beyond reach" rather than "within reach": a NaN distance counts as touching, so that it
  // reaches the forces and the finite check
  const bool touches = !(dist2 >= reach * reach) & (dist2 != 0.0);
  found[count] = {d, e, to};
  count += touches;
  if constexpr (History) {
    const std::uint64_t keep = 0ull - static_cast<std::uint64_t>(touches);
    a.history[e] = std::bit_cast<double>(std::bit_cast<std::uint64_t>(a.history[e]) & keep);
  }
  return {dist2, reach, i, j};
}

/// The stretch's rows [r0, r1) of a block that ends at row `last`: every entry tested, and the
/// candidates written down from the stretch's first entry on (their count into `kept`). `slot`
/// is the block's next deferred slot, and moves past the stretch's. Returns the touching count.
template <bool History>
[[gnu::always_inline]] inline std::size_t
touching_choosing_candidates(const BlockArrays& a, ContactCandidates& c, std::ptrdiff_t r0,
                             std::ptrdiff_t r1, std::ptrdiff_t last, std::uint32_t& slot,
                             std::uint32_t& kept, TouchingEntry* found) {
  std::size_t count = 0;
  const std::uint32_t base = a.offset[r0];
  std::uint32_t* entry = c.entry.data();
  std::uint32_t* entry_slot = c.slot.data();
  const double skin = c.skin;
  kept = 0;
  for (std::uint32_t e = a.offset[r0]; e < a.offset[r1]; ++e) {
    const auto later = static_cast<std::uint32_t>(a.neighbour[e] >= last); // a later block
    const std::uint32_t later_mask = 0u - later;
    const std::uint32_t to = (slot & later_mask) | ~later_mask;
    const EntryGap g = test_entry<History>(a, r0, e, to, found, count);
    const double cut = g.reach + skin;
    entry[base + kept] = e;
    entry_slot[base + kept] = to;
    const bool pinned = (a.kind[g.i] != Kind::free) | (a.kind[g.j] != Kind::free);
    kept += !(g.dist2 >= cut * cut) | pinned;
    slot += later;
  }
  return count;
}

/// The stretch from row r0 whose `kept` candidates were written down: only those tested.
/// Returns the touching count.
template <bool History>
[[gnu::always_inline]] inline std::size_t
touching_candidates(const BlockArrays& a, const ContactCandidates& c, std::ptrdiff_t r0,
                    std::uint32_t kept, TouchingEntry* found) {
  std::size_t count = 0;
  const std::uint32_t* entry = c.entry.data();
  const std::uint32_t* entry_slot = c.slot.data();
  const std::uint32_t base = a.offset[r0], end = base + kept;
  for (std::uint32_t k = base; k < end; ++k)
    test_entry<History>(a, r0, entry[k], entry_slot[k], found, count);
  return count;
}

} // namespace talus
