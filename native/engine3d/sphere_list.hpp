#pragma once
// The Verlet list of spheres: every pair within reach (touching, or closer than the skin) as a
// half list (j > i) in CSR form, each entry with the periodic image of j it takes and the
// tangential spring of the contact (and its rolling spring, where the materials roll with
// resistance), and every sphere-plate pair with its springs.
#include <cstdint>
#include <vector>

#include "engine3d/plate_drivers.hpp"
#include "engine3d/spheres.hpp"

namespace talus {

/// Periodic image of j in a pair entry: j is taken at r_j + (sx L_x, sy L_y, sz L_z).
struct Shift3 {
  std::int8_t x = 0, y = 0, z = 0;
  friend bool operator==(Shift3, Shift3) = default;
};

struct SphereList {
  std::vector<std::uint32_t> row_offset; ///< entries row_offset[i] .. row_offset[i+1] have i first
  std::vector<std::uint32_t> neighbour;  ///< j > i, ascending within a row
  std::vector<Shift3> shift;
  std::vector<Vec3> spring; ///< tangential spring (m) of each entry, 0 when not touching
  /// CSR over spheres: the entries whose second sphere is k, ascending (a sphere adds the forces
  /// of those from earlier force blocks in this order, whatever the threads: force_pass3.hpp).
  std::vector<std::uint32_t> second_offset;
  std::vector<std::uint32_t> second_entry;
  std::vector<std::uint32_t> plate_offset; ///< CSR over spheres: their plates within reach
  std::vector<std::uint32_t> plate;
  std::vector<Vec3> plate_spring;
  /// Whether the entries keep tangential springs (`spring`, `plate_spring`): where the tangential
  /// law has a history (talus/law_table.hpp, keeps_history); else both are empty. Set before the
  /// first build; builds keep it.
  bool with_springs = true;
  /// Whether the entries keep rolling springs: `rolling` beside `spring` and `plate_rolling`
  /// beside `plate_spring` (the rolling angle, rad, a vector in the tangent plane), else both
  /// are empty. Set before the first build; builds keep it.
  bool with_rolling = false;
  std::vector<Vec3> rolling;
  std::vector<Vec3> plate_rolling;
  std::vector<Vec3> reference;            ///< sphere positions at the last build
  std::vector<PlatePose> plate_reference; ///< the plates' poses at the last build
  Vec3 box{};                ///< the domain's size at the last build (a deforming cell changes it)
  double shear_offset = 0.0; ///< the domain's Lees-Edwards offset at the last build
  double skin = 0.0;
  std::uint64_t builds = 0;

  std::size_t pair_count() const { return neighbour.size(); }
  /// The tangential spring of pair entry e, or of sphere-plate entry e: 0 where the list keeps
  /// none (a law without history).
  Vec3 spring_at(std::size_t e) const { return with_springs ? spring[e] : Vec3{}; }
  Vec3 plate_spring_at(std::size_t e) const { return with_springs ? plate_spring[e] : Vec3{}; }
  /// Where entry's image of j is, less j.
  Vec3 offset(std::size_t entry, const Domain3& d) const {
    return d.image_shift(shift[entry].x, shift[entry].y, shift[entry].z);
  }
  /// The velocity of entry's image of j less j's: the Lees-Edwards images' slide.
  Vec3 image_velocity(std::size_t entry, const Domain3& d) const {
    return {shift[entry].y * d.shear_velocity, 0.0, 0.0};
  }
};

/// Rebuilds the list with the given skin (m). Wraps positions into the domain along periodic
/// axes first (a sphere that crosses a Lees-Edwards side takes the images' slide off its
/// velocity). Pairs of two spheres that are not free are left out. The springs (and rolling
/// springs) of pairs still within reach are carried over, where the list keeps them. Throws
/// InvalidArgument if a periodic axis is shorter than three interaction ranges (2 max radius +
/// skin): a sphere would meet j through two images.
void build_sphere_list(SphereList& list, Spheres& s, const std::vector<Plane>& plates,
                       const Domain3& domain, double skin);

/// The spheres in the order of the cells (at least `range` wide) they lie in, the cells taken
/// x fastest, then y, then z: a sphere's neighbours lie near it in this order.
std::vector<std::uint32_t> spheres_by_cell(const Spheres& s, const Domain3& domain, double range);

/// Fills second_offset and second_entry from the rows' neighbours (`spheres` rows).
void index_second_entries(SphereList& list, std::size_t spheres);

/// True when some sphere or some point of a plate near the spheres moved more than half the skin
/// since the last build (a turned plate's points move by the turn times their distance from its
/// centre, bounded by the farthest sphere's), or the spheres or plates are not those of the build.
/// A box that shrank or a Lees-Edwards offset that moved since the build (a deforming cell,
/// whose remap moves the build positions with the spheres) takes its share of the skin first
/// (cell_reserve).
bool list_is_stale(const SphereList& list, const Spheres& s, const std::vector<Plane>& plates,
                   const Domain3& domain);

/// How much closer a pair the list left out may have come through the cell's deformation since
/// the build, m: -ln(the smallest side's shrink) times the reach plus skin (a pair left out was
/// at least that apart; -ln bounds the sum of the steps' shrinks), plus the distance the
/// Lees-Edwards images slid. 0 for a box as it was built.
double cell_reserve(const SphereList& list, const Domain3& domain, const Spheres& s);

} // namespace talus
