#pragma once
// What one force block works on (NeighbourList: force blocks): the particles' and the list's
// arrays by plain pointers, so that a store through one cannot move another (no reloads), and
// the touching entries a first pass over a stretch of rows hands to the pair pass.
#include <cstddef>
#include <cstdint>

#include "core/contact_vectors.hpp"
#include "neighbours/neighbour_list.hpp"
#include "state/particles.hpp"

namespace talus {

/// Rows per stretch: their particles' data stays in the L1 cache between the two passes.
inline constexpr std::ptrdiff_t stretch_rows = NeighbourList::stretch_rows;

/// A list entry found touching over a stretch of rows.
struct TouchingEntry {
  Vec2 d; ///< r_i - r_j (the image of j)
  std::uint32_t entry;
  std::uint32_t slot; ///< its deferred slot, or no_slot if its second particle is in the block
};
inline constexpr std::uint32_t no_slot = ~std::uint32_t{0};

struct BlockArrays {
  Particles& p; ///< forces and torques are added through it
  const Vec2* position;
  const double* radius;
  const double* mass;
  const Vec2* velocity;
  const double* spin;
  const std::uint16_t* material;
  const Kind* kind;
  const std::uint32_t* offset;    ///< NeighbourList::row_offset
  const std::uint32_t* neighbour; ///< NeighbourList::neighbour
  const ImageShift* images;
  const std::uint8_t* row_in_stretch; ///< NeighbourList::entry_row
  double* history;
  PairForce* slots;      ///< the deferred pair forces
  Vec2 box;              ///< the domain's size, for periodic images
  double shear_offset;   ///< m: Domain::shear_offset, the images across y along x
  double shear_velocity; ///< m/s: Domain::shear_velocity, their velocity along x

  BlockArrays(Particles& particles, NeighbourList& list, PairForce* deferred, const Domain& d)
      : p(particles), position(p.position.data()), radius(p.radius.data()), mass(p.mass.data()),
        velocity(p.velocity.data()), spin(p.angular_velocity.data()), material(p.material.data()),
        kind(p.kind.data()), offset(list.row_offset.data()), neighbour(list.neighbour.data()),
        images(list.image.data()), row_in_stretch(list.entry_row.data()),
        history(list.history.data()), slots(deferred), box(d.size()), shear_offset(d.shear_offset),
        shear_velocity(d.shear_velocity) {}
};

} // namespace talus
