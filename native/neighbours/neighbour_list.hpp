#pragma once
// The Verlet list: every pair within reach (touching, or closer than the skin), as a half list
// (j > i) in CSR form, with the tangential history of each pair stored beside its entry.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/domain.hpp"
#include "state/particles.hpp"
#include "state/walls.hpp"

namespace talus {

/// Periodic image of j in a pair entry: j is taken at r_j + (sx L_x, sy L_y), and along x also
/// sy times the images' Lees-Edwards offset (Domain::image_shift).
struct ImageShift {
  std::int8_t sx = 0;
  std::int8_t sy = 0;
  friend bool operator==(ImageShift, ImageShift) = default;
};

struct NeighbourList {
  // particle pairs: entries row_offset[i] .. row_offset[i+1] have i as first particle
  std::vector<std::uint32_t> row_offset;
  std::vector<std::uint32_t> neighbour; ///< j > i, sorted within a row
  std::vector<ImageShift> image;
  std::vector<double> history; ///< tangential spring s (m) of each pair, 0 when not touching
  /// Whether the list keeps `history` and `wall_history` (sized to the entries, carried across
  /// builds and renumberings) or leaves them empty: a tangential law without a spring needs none
  /// (Simulation sets it; not saved, it follows from the law).
  bool keeps_history = true;
  /// The rolling spring's angle theta (rad) of each pair (src/talus/rolling_resistance.hpp),
  /// seen from its first particle, 0 when not touching; like `history`, kept only when
  /// `keeps_rolling` (a scene with rolling resistance), else empty.
  std::vector<double> rolling;
  bool keeps_rolling = false;
  // Force blocks (derived from the rows by index_force_blocks): rows are cut into blocks of
  // block_rows, a number that depends on the particle count only. An entry whose second particle
  // lies beyond its row's block is deferred: its force waits in a slot (numbered in entry order)
  // and is added once every block is done, so blocks can run side by side on any thread count.
  std::uint32_t block_rows = 0;
  std::vector<std::uint32_t> block_first_slot; ///< first deferred slot of each block, then total
  std::vector<std::uint32_t> deferred_offset;  ///< CSR over particles: deferred slots whose
  std::vector<std::uint32_t> deferred_slot;    ///< second particle is k, in entry order
  /// Particles whose force is complete only after every block: those with deferred entries or
  /// wall contacts, in order.
  std::vector<std::uint32_t> late;
  /// The force stage goes through a block's rows by stretches of this many, from the block's
  /// first row.
  static constexpr std::uint32_t stretch_rows = 64;
  /// The row (first particle) of each entry, less the first row of its stretch, so that the
  /// force stage can walk a stretch of entries in one flat loop (no inner loop whose length
  /// changes from row to row). One byte, not four: it is read for every entry every step.
  std::vector<std::uint8_t> entry_row;
  bool is_late(std::size_t k) const {
    return deferred_offset[k + 1] > deferred_offset[k] || wall_offset[k + 1] > wall_offset[k];
  }
  // particle-segment pairs, CSR over particles
  std::vector<std::uint32_t> wall_offset;
  std::vector<std::uint32_t> wall_segment;
  std::vector<double> wall_history;
  std::vector<double> wall_rolling; ///< theta of each particle-segment pair, as `rolling`

  std::vector<Vec2> reference;         ///< particle positions at the last build
  std::vector<Vec2> segment_reference; ///< segment end points (a, b, a, b, ...) at the last build
  double skin = 0.0;
  std::uint64_t builds = 0;
  /// The box's size at the last build (m): a deforming cell's strain since then closes gaps
  /// the skin must also cover (Simulation, "Deforming cell").
  Vec2 box{};
  /// The domain's Lees-Edwards offset at the last build (m): its change since then moves the
  /// images across y by as much, which the skin must also cover.
  double shear_offset = 0.0;

  std::size_t pair_count() const { return neighbour.size(); }
  Vec2 shift(std::size_t entry, const Domain& d) const {
    return d.image_shift(image[entry].sx, image[entry].sy);
  }
  /// The velocity of j's image in entry e less j's own (Lees-Edwards; 0 without).
  Vec2 image_velocity(std::size_t entry, const Domain& d) const {
    return {image[entry].sy * d.shear_velocity, 0.0};
  }
};

/// Rows per force block for n particles: n cut into 2, 4, 8 or 16 blocks (a power of two, so that
/// 2, 4, 8 or 16 threads share them evenly) of at least 2048 rows each where n allows. A function
/// of n only, so that results do not depend on the thread count. Not more blocks than that: an
/// entry that crosses a block's end costs more than one that does not (its deferred slot and its
/// late particle), and a block's end crosses a whole layer of the packing.
std::uint32_t force_block_rows(std::size_t n);

/// Fills the force-block fields of a list from its rows and wall contacts (build_neighbour_list
/// calls it; a list read back from a checkpoint needs it too).
void index_force_blocks(NeighbourList& list, int threads = 1);

/// True when some particle or wall end point moved more than half the skin since the last build.
bool needs_rebuild(const NeighbourList& list, const Particles& p, const Segments& walls);

/// The squared move (m^2) past which the list may miss a pair: half the skin, squared.
inline double drift_limit2(const NeighbourList& list) {
  return 0.25 * list.skin * list.skin;
}

/// The largest squared distance a particle moved since the last build (m^2), or infinity when
/// the particles are not those of the build (another count). A NaN position does not count.
double largest_drift2(const NeighbourList& list, const Particles& p, int threads = 1);

/// True when some particle moved more than half the skin since the last build, or the particles
/// are not those of the build (another count).
bool particles_moved(const NeighbourList& list, const Particles& p, int threads = 1);

/// True when a wall end point, or one of the given (driven) particles, moved more than half the
/// skin since the last build: the part of the drift test the integrator does not do.
bool walls_moved(const NeighbourList& list, const Particles& p, const Segments& walls,
                 const std::vector<std::uint32_t>& driven);

/// The same list for renumbered particles (Particles::permute with `order`; new_of_old is its
/// inverse): every pair keeps its history, an entry whose new first particle is the later one
/// is turned round (its image negated; the tangential spring is the same seen from either
/// side), rows are sorted again, the wall rows and build positions follow their particles and
/// the force blocks are indexed again.
void renumber_neighbour_list(NeighbourList& list, const std::vector<std::uint32_t>& order,
                             const std::vector<std::uint32_t>& new_of_old, int threads = 1);

/// Rebuilds the list. Wraps positions into the domain along periodic directions first (a grain
/// that crosses a Lees-Edwards side takes the image's velocity off its own). Pairs of
/// two non-free particles are left out. History of pairs still within reach is carried over.
/// Throws InvalidArgument if a periodic direction is shorter than 3 interaction ranges, or if a
/// Lees-Edwards offset is outside [0, L_x) (Simulation keeps it there at each build).
/// `threads` build the rows side by side, in contiguous blocks joined in order: the list is the
/// same whatever the count.
void build_neighbour_list(NeighbourList& list, Particles& p, const Segments& walls,
                          const Domain& domain, double skin, int threads = 1);

} // namespace talus
