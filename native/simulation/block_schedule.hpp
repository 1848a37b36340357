#pragma once
// The schedule of the force stage's blocks (NeighbourList: force blocks): the order in which the
// threads take them, and the time each one took. The threads take the blocks one at a time, the
// longest first by the time each took in the last stages, so that a thread that finishes early
// takes more and the last ones, when a thread may wait, are short: the blocks' times change from
// step to step by more than a fixed share per thread could follow (docs/performance.md, "Force
// blocks"). Which thread runs a block changes no result, since a block's sums are its own.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace talus {

/// The order in which the threads take the force blocks (into `order`, resized; no allocation
/// once it has the size): the block indices by decreasing `work` (one figure per block, as the
/// last force stage measured it), equal ones by index.
void force_block_order(const std::vector<std::uint64_t>& work, std::vector<std::ptrdiff_t>& order);

class BlockSchedule {
public:
  using Clock = std::chrono::steady_clock;
  /// Before a force stage of `blocks` blocks (a new count forgets the times): the order.
  void plan(std::size_t blocks);
  /// The block taken `taken`-th.
  std::ptrdiff_t block(std::ptrdiff_t taken) const {
    return order_[static_cast<std::size_t>(taken)];
  }
  /// Block b, started at `start`, is done: its time is kept, smoothed over steps (a quarter of
  /// the newest). It counts what a count of entries and contacts would miss: the correction and
  /// prediction of its particles and the memory it waits on. Threads record different blocks.
  void record(std::ptrdiff_t b, Clock::time_point start);
  std::size_t footprint_bytes() const;

private:
  std::vector<std::uint64_t> work_; ///< each block's time in the last force stages (ns, smoothed)
  std::vector<std::ptrdiff_t> order_;
};

} // namespace talus
