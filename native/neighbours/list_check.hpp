#pragma once
// Whether a neighbour list read back from a checkpoint fits the particles and walls it came with:
// the force stage indexes every array of it without checks, so a list that does not fit (written
// by a defective build, or made by hand) must be refused before the first step.
#include <cstddef>
#include <string>

#include "neighbours/neighbour_list.hpp"

namespace talus {

/// What does not fit, in words ("row offsets not ascending"), or "" when the list fits
/// `particles` particles and `walls` wall segments.
std::string neighbour_list_problem(const NeighbourList& list, std::size_t particles,
                                   std::size_t walls);

} // namespace talus
