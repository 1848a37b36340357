#pragma once
// Which held or free grains rest on which: the frost front lifts a grain with those under it.
// Held grains are not in the engine's neighbour list (it pairs a grain with a free one only), so
// the pairs are found here, on a grid of their own.
#include <cstdint>
#include <utility>
#include <vector>

#include "state/particles.hpp"

namespace talus {

/// The pairs (lower, upper) of `grains` less than a tenth of the smaller radius apart (one
/// call's differential heave cannot close a wider gap), each once: binned on a grid of cells
/// `cell` wide over [x_min - cell, x_max + cell] (grains beyond it in the edge cells) and the
/// grains' heights, a large grain in every cell its box covers.
std::vector<std::pair<std::uint32_t, std::uint32_t>>
resting_pairs(const Particles& p, const std::vector<std::uint32_t>& grains, double cell,
              double x_min, double x_max);

} // namespace talus
