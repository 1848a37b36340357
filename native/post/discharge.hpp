#pragma once
// The discharge of a silo, hopper or hourglass as an experimenter measures it: the grains that
// came through the orifice against time, the steady part of the flow found from the data (or
// given), the rate over it with its uncertainty, and whether the flow ended by clogging.
// A clogged flow has no rate, whatever the window.
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/frame.hpp"

namespace talus {

/// The opening grains leave through: the segment from (x0, y) to (x1, y).
struct Orifice {
  double y = 0.0;
  double x0 = 0.0, x1 = 0.0;
};

/// How a record of the flow ends.
enum class FlowEnd {
  flowing, ///< grains were still coming through at the last snapshot
  drained, ///< the flow stopped with nothing left over the orifice
  clogged, ///< the flow stopped with grains resting over the orifice (an arch)
};

const char* to_string(FlowEnd e);

/// One stretch of the flow: grains per second from one snapshot to another.
struct FlowBlock {
  double from = 0.0, to = 0.0; ///< s
  double rate = 0.0;           ///< grains/s
};

struct Discharge {
  std::vector<double> time;       ///< s, one per snapshot
  std::vector<std::size_t> below; ///< free grains with centre below the orifice
  std::size_t passed = 0;         ///< grains that came through over the record
  double first_passage = 0.0;     ///< s: the first snapshot with a grain more below
  double last_passage = 0.0;      ///< s: the snapshot from which the count no longer changed
  FlowEnd end = FlowEnd::flowing;
  /// The flowing part cut into blocks of about `grains_per_block` grains (at most 20 blocks);
  /// the window is taken from them.
  std::vector<FlowBlock> blocks;
  double median_rate = 0.0; ///< grains/s: the median of the blocks' rates
  bool window_given = false;
  double window_from, window_to; ///< s (NaN without a rate)
  /// grains/s: least-squares slope of the count over the window's snapshots; NaN when the
  /// flow clogged or too few grains came through (see `why_no_rate`).
  double rate;
  double rate_error;       ///< grains/s: standard error from the scatter of the window's blocks
  double intercept;        ///< the fitted count at t = 0: count = intercept + rate t
  double rate_first_half;  ///< the same fit over the first and the second half of the window:
  double rate_second_half; ///< equal for a steady flow
  std::string why_no_rate; ///< empty when there is a rate
};

struct DischargeOptions {
  /// s: the window to fit; none: the steady part, found as `discharge` documents.
  std::optional<std::pair<double, double>> window;
};

/// Grains in one block of the flow, on average: enough that counting noise stays small.
inline constexpr std::size_t grains_per_block = 20;
/// A block belongs to the steady part unless its rate is below this fraction of the median.
inline constexpr double steady_fraction = 0.8;

/// The discharge through `orifice` seen in `frames`. The flow has stopped when no grain came
/// through for the last stretch of the record, at least three snapshot intervals and five mean
/// intervals between grains long; it is clogged if a free grain's centre then lies over the
/// orifice, else drained. The steady window: the flowing part (first to last passage) is cut
/// into blocks of about `grains_per_block` grains; the window runs from the first block whose
/// rate reaches `steady_fraction` of the median block rate to the last such block, which leaves
/// out the flow's start and its final draining. A clogged flow, or fewer than two blocks'
/// worth of grains, gets no rate. Throws InvalidArgument for a window with fewer than three
/// snapshots.
Discharge discharge(const std::vector<Frame>& frames, const Orifice& orifice,
                    const DischargeOptions& options = {});

} // namespace talus
