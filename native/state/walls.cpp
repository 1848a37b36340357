#include "state/walls.hpp"

namespace talus {

std::size_t join_segment_ends(Segments& walls, double tolerance) {
  std::vector<Vec2*> ends;
  for (Segment& s : walls) ends.push_back(&s.a), ends.push_back(&s.b);
  std::size_t moved = 0;
  const double t2 = tolerance * tolerance;
  for (std::size_t k = 1; k < ends.size(); ++k)
    for (std::size_t m = 0; m < k; ++m) {
      if (*ends[m] == *ends[k] || norm2(*ends[m] - *ends[k]) > t2) continue;
      *ends[k] = *ends[m];
      ++moved;
      break;
    }
  return moved;
}

} // namespace talus
