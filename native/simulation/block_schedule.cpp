#include "simulation/block_schedule.hpp"

#include <algorithm>

namespace talus {

void force_block_order(const std::vector<std::uint64_t>& work, std::vector<std::ptrdiff_t>& order) {
  order.resize(work.size());
  for (std::size_t b = 0; b < order.size(); ++b) order[b] = static_cast<std::ptrdiff_t>(b);
  std::stable_sort(order.begin(), order.end(), [&](std::ptrdiff_t x, std::ptrdiff_t y) {
    return work[static_cast<std::size_t>(x)] > work[static_cast<std::size_t>(y)];
  });
}

void BlockSchedule::plan(std::size_t blocks) {
  if (work_.size() != blocks) work_.assign(blocks, 0);
  force_block_order(work_, order_);
}

void BlockSchedule::record(std::ptrdiff_t b, Clock::time_point start) {
  const auto ns = static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start).count());
  std::uint64_t& w = work_[static_cast<std::size_t>(b)];
  w = w == 0 ? ns + 1 : (3 * w + ns) / 4 + 1;
}

std::size_t BlockSchedule::footprint_bytes() const {
  return work_.capacity() * sizeof(std::uint64_t) + order_.capacity() * sizeof(std::ptrdiff_t);
}

} // namespace talus
