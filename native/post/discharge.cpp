#include "post/discharge.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/core.h>

#include "post/flow_profiles.hpp"
#include "talus/error.hpp"

namespace talus {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

std::size_t count_below(const Frame& f, double y) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < f.position.size(); ++i)
    if (f.kind[i] == 0 && f.position[i].y < y) ++n;
  return n;
}

bool grain_over(const Frame& f, const Orifice& o) {
  for (std::size_t i = 0; i < f.position.size(); ++i) {
    const Vec2 r = f.position[i];
    if (f.kind[i] == 0 && r.y > o.y && r.x > o.x0 && r.x < o.x1) return true;
  }
  return false;
}

// Least-squares line through the snapshots a..b (inclusive): slope and intercept.
std::pair<double, double> fit_line(const Discharge& d, std::size_t a, std::size_t b) {
  std::vector<double> t(d.time.begin() + static_cast<std::ptrdiff_t>(a),
                        d.time.begin() + static_cast<std::ptrdiff_t>(b + 1));
  std::vector<double> n;
  for (std::size_t k = a; k <= b; ++k) n.push_back(static_cast<double>(d.below[k]));
  const double s = slope(t, n);
  double mt = 0.0, mn = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k) mt += t[k], mn += n[k];
  mt /= static_cast<double>(t.size()), mn /= static_cast<double>(t.size());
  return {s, mn - s * mt};
}

// Snapshots a..b cut into blocks of about grains_per_block grains each (at least one interval
// per block, at most 20 blocks).
std::vector<FlowBlock> cut_blocks(const Discharge& d, std::size_t a, std::size_t b) {
  const std::size_t grains = d.below[b] > d.below[a] ? d.below[b] - d.below[a] : 0;
  const std::size_t intervals = b - a;
  const std::size_t k =
      std::clamp<std::size_t>(grains / grains_per_block, 1, std::min<std::size_t>(20, intervals));
  std::vector<FlowBlock> blocks;
  for (std::size_t j = 0; j < k; ++j) {
    const std::size_t p = a + j * intervals / k, q = a + (j + 1) * intervals / k;
    const double dt = d.time[q] - d.time[p];
    const double dn = static_cast<double>(d.below[q]) - static_cast<double>(d.below[p]);
    blocks.push_back({d.time[p], d.time[q], dt > 0.0 ? dn / dt : 0.0});
  }
  return blocks;
}

double median_rate(std::vector<FlowBlock> blocks) {
  if (blocks.empty()) return 0.0;
  const auto mid = blocks.begin() + static_cast<std::ptrdiff_t>(blocks.size() / 2);
  std::nth_element(blocks.begin(), mid, blocks.end(),
                   [](const FlowBlock& x, const FlowBlock& y) { return x.rate < y.rate; });
  return mid->rate;
}

// The index of the first snapshot at or after t (the last one if none).
std::size_t at_or_after(const std::vector<double>& time, double t) {
  const auto it = std::lower_bound(time.begin(), time.end(), t);
  return it == time.end() ? time.size() - 1 : static_cast<std::size_t>(it - time.begin());
}

// How the record ends, from when the count last changed and what lies over the orifice.
void find_end(Discharge& d, const std::vector<Frame>& frames, const Orifice& o) {
  const std::size_t last = d.below.size() - 1;
  std::size_t settled = last; // the first snapshot from which the count stays as at the end
  while (settled > 0 && d.below[settled - 1] == d.below[last]) --settled;
  std::size_t first = 0;
  while (first < last && d.below[first] == d.below.front()) ++first;
  d.first_passage = d.time[first], d.last_passage = d.time[settled];
  d.passed = d.below[last] > d.below.front() ? d.below[last] - d.below.front() : 0;
  const double interval = (d.time[last] - d.time.front()) / static_cast<double>(last);
  const double between = d.passed > 0 ? (d.last_passage - d.first_passage) /
                                            static_cast<double>(std::max<std::size_t>(d.passed, 1))
                                      : 0.0;
  const double quiet = d.time[last] - d.last_passage;
  const bool stopped = d.passed == 0 || quiet >= std::max(3.0 * interval, 5.0 * between);
  if (!stopped)
    d.end = FlowEnd::flowing;
  else
    d.end = grain_over(frames.back(), o) ? FlowEnd::clogged : FlowEnd::drained;
}

// The window and the fits over it.
void fit_window(Discharge& d, const DischargeOptions& options) {
  const std::size_t last = d.below.size() - 1;
  std::size_t a = 0, b = 0;
  if (options.window) {
    d.window_given = true;
    a = at_or_after(d.time, options.window->first);
    b = at_or_after(d.time, options.window->second);
    if (b > 0 && d.time[b] > options.window->second) --b;
    if (b < a + 2 || d.time[a] > options.window->second)
      throw InvalidArgument(fmt::format("--window {},{}: it holds fewer than three snapshots",
                                        options.window->first, options.window->second));
    d.blocks = cut_blocks(d, a, b);
    d.median_rate = median_rate(d.blocks);
  } else {
    // the flowing part: from the snapshot before the first passage to the last passage (or the
    // end of the record, while the flow goes on)
    const std::size_t from = at_or_after(d.time, d.first_passage);
    const std::size_t to = d.end == FlowEnd::flowing ? last : at_or_after(d.time, d.last_passage);
    const std::size_t start = from > 0 ? from - 1 : 0;
    if (to <= start) return;
    d.blocks = cut_blocks(d, start, to);
    d.median_rate = median_rate(d.blocks);
    std::size_t p = 0, q = d.blocks.size() - 1;
    while (p < q && d.blocks[p].rate < steady_fraction * d.median_rate) ++p;
    while (q > p && d.blocks[q].rate < steady_fraction * d.median_rate) --q;
    d.blocks = std::vector<FlowBlock>(d.blocks.begin() + static_cast<std::ptrdiff_t>(p),
                                      d.blocks.begin() + static_cast<std::ptrdiff_t>(q + 1));
    a = at_or_after(d.time, d.blocks.front().from);
    b = at_or_after(d.time, d.blocks.back().to);
  }
  d.window_from = d.time[a], d.window_to = d.time[b];
  std::tie(d.rate, d.intercept) = fit_line(d, a, b);
  const std::size_t half = a + (b - a) / 2;
  d.rate_first_half = fit_line(d, a, std::max(half, a + 1)).first;
  d.rate_second_half = fit_line(d, std::min(half, b - 1), b).first;
  const auto k = static_cast<double>(d.blocks.size());
  if (d.blocks.size() >= 3) {
    double mean = 0.0, var = 0.0;
    for (const FlowBlock& x : d.blocks) mean += x.rate / k;
    for (const FlowBlock& x : d.blocks) var += (x.rate - mean) * (x.rate - mean) / (k - 1.0);
    d.rate_error = std::sqrt(var / k);
  }
}

} // namespace

const char* to_string(FlowEnd e) {
  switch (e) {
  case FlowEnd::flowing:
    return "flowing";
  case FlowEnd::drained:
    return "drained";
  case FlowEnd::clogged:
    return "clogged";
  }
  return "?";
}

Discharge discharge(const std::vector<Frame>& frames, const Orifice& orifice,
                    const DischargeOptions& options) {
  Discharge d;
  d.rate = d.rate_error = d.intercept = d.rate_first_half = d.rate_second_half = nan;
  d.window_from = d.window_to = nan;
  for (const Frame& f : frames) {
    d.time.push_back(f.time);
    d.below.push_back(count_below(f, orifice.y));
  }
  if (d.time.size() < 3) {
    d.why_no_rate = "fewer than three snapshots";
    return d;
  }
  find_end(d, frames, orifice);
  if (d.end == FlowEnd::clogged) {
    d.why_no_rate =
        fmt::format("clogged at t = {:.4g} s, after {} grains", d.last_passage, d.passed);
    return d;
  }
  if (!options.window && d.passed < 2 * grains_per_block) {
    d.why_no_rate = fmt::format("only {} grains came through; a rate needs {} at least", d.passed,
                                2 * grains_per_block);
    return d;
  }
  fit_window(d, options);
  return d;
}

} // namespace talus
