#include "neighbours/list_check.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace talus {

namespace {

// A CSR table over `rows` rows of `entries` entries, each naming one of `count` things.
std::string csr_problem(const std::vector<std::uint32_t>& offset,
                        const std::vector<std::uint32_t>& entries, std::size_t rows,
                        std::size_t count, const char* what) {
  const std::string name(what);
  if (offset.size() != rows + 1) return name + " offsets: not one per particle and one more";
  if (offset.front() != 0 || offset.back() != entries.size())
    return name + " offsets: not from 0 to the number of entries";
  if (!std::is_sorted(offset.begin(), offset.end())) return name + " offsets: not ascending";
  if (std::any_of(entries.begin(), entries.end(), [&](std::uint32_t k) { return k >= count; }))
    return name + " entries: an index beyond the " + std::to_string(count) + " there are";
  return "";
}

} // namespace

std::string neighbour_list_problem(const NeighbourList& l, std::size_t particles,
                                   std::size_t walls) {
  if (std::string p = csr_problem(l.row_offset, l.neighbour, particles, particles, "pair");
      !p.empty())
    return p;
  if (std::string p = csr_problem(l.wall_offset, l.wall_segment, particles, walls, "wall");
      !p.empty())
    return p;
  if (l.image.size() != l.neighbour.size()) return "periodic images: not one per pair";
  if (!l.history.empty() && l.history.size() != l.neighbour.size())
    return "springs: not one per pair";
  if (!l.wall_history.empty() && l.wall_history.size() != l.wall_segment.size())
    return "wall springs: not one per wall contact";
  if (!l.rolling.empty() && l.rolling.size() != l.neighbour.size())
    return "rolling springs: not one per pair";
  if (!l.wall_rolling.empty() && l.wall_rolling.size() != l.wall_segment.size())
    return "wall rolling springs: not one per wall contact";
  // build positions of another count (none, say) only make the first step rebuild the list
  // (largest_drift2, walls_moved): they are allowed
  return "";
}

} // namespace talus
