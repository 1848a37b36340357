#include "post/segregation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "talus/error.hpp"

namespace talus {

namespace {

// Nearest-rank percentile: the smallest value with at least a share q of the values at or below.
double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
  const std::size_t k = std::clamp<std::size_t>(rank, 1, v.size()) - 1;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

double split_radius(const Frame& f) {
  std::vector<double> r;
  for (std::size_t i = 0; i < f.radius.size(); ++i)
    if (f.kind[i] == 0) r.push_back(f.radius[i]);
  if (r.empty()) throw InvalidArgument("segregation: the first snapshot has no free grains");
  const double median = percentile(r, 0.5);
  const double largest = *std::max_element(r.begin(), r.end());
  if (largest >= 1.5 * median) return 1.5 * median;
  return percentile(r, 0.9);
}

} // namespace

SegregationSeries segregation(const std::vector<Frame>& frames, double large_radius) {
  SegregationSeries s;
  if (frames.empty()) return s;
  const Frame& first = frames.front();
  s.large_radius = large_radius > 0.0 ? large_radius : split_radius(first);
  std::vector<std::pair<double, std::uint32_t>> by_size;
  for (std::size_t i = 0; i < first.radius.size(); ++i)
    if (first.kind[i] == 0) {
      by_size.emplace_back(first.radius[i], first.id[i]);
      if (first.radius[i] >= s.large_radius) ++s.large_count;
    }
  if (s.large_count == 0 || s.large_count == by_size.size())
    throw InvalidArgument("segregation: the split at R = " + std::to_string(s.large_radius) +
                          " m leaves no large or no small grains");
  std::sort(by_size.begin(), by_size.end(), [](auto a, auto b) { return a.first > b.first; });
  for (std::size_t k = 0; k < std::min<std::size_t>(6, by_size.size()); ++k)
    s.largest.push_back(by_size[k].second);

  for (const Frame& f : frames) {
    double bottom = std::numeric_limits<double>::max();
    std::vector<double> tops;
    std::unordered_map<std::uint32_t, std::size_t> index_of;
    for (std::size_t i = 0; i < f.position.size(); ++i) {
      if (f.kind[i] != 0) continue;
      bottom = std::min(bottom, f.position[i].y - f.radius[i]);
      tops.push_back(f.position[i].y + f.radius[i]);
      index_of[f.id[i]] = i;
    }
    if (tops.empty()) continue;
    const double top = percentile(tops, 0.98), bed = std::max(top - bottom, 1e-300);
    double large = 0, small = 0;
    std::size_t nl = 0, ns = 0;
    for (std::size_t i = 0; i < f.position.size(); ++i) {
      if (f.kind[i] != 0) continue;
      const double h = f.position[i].y - bottom;
      if (f.radius[i] >= s.large_radius)
        large += h, ++nl;
      else
        small += h, ++ns;
    }
    s.time.push_back(f.time);
    s.bed_height.push_back(bed);
    s.index.push_back(
        nl && ns ? (large / static_cast<double>(nl) - small / static_cast<double>(ns)) / bed : 0.0);
    std::vector<double> heights;
    for (const std::uint32_t id : s.largest) {
      const auto it = index_of.find(id);
      heights.push_back(it == index_of.end() ? std::nan("") : f.position[it->second].y - bottom);
    }
    s.largest_height.push_back(heights);
    const auto it = index_of.find(s.largest.front());
    s.largest_depth_fraction.push_back(
        it == index_of.end() ? std::nan("")
                             : (top - f.position[it->second].y - f.radius[it->second]) / bed);
  }
  return s;
}

ConvectionProfile convection(const std::vector<Frame>& frames, double large_radius,
                             std::size_t bins) {
  ConvectionProfile c;
  if (frames.size() < 2 || bins == 0) return c;
  double x0 = std::numeric_limits<double>::max(), x1 = -x0;
  for (std::size_t i = 0; i < frames.front().position.size(); ++i)
    if (frames.front().kind[i] == 0) {
      x0 = std::min(x0, frames.front().position[i].x - frames.front().radius[i]);
      x1 = std::max(x1, frames.front().position[i].x + frames.front().radius[i]);
    }
  if (!(x1 > x0)) return c;
  const double w = (x1 - x0) / static_cast<double>(bins);
  std::vector<double> sum(bins);
  c.count.assign(bins, 0);
  for (std::size_t k = 1; k < frames.size(); ++k) {
    const Frame &a = frames[k - 1], &b = frames[k];
    const double dt = b.time - a.time;
    if (!(dt > 0.0)) continue;
    std::unordered_map<std::uint32_t, std::size_t> in_a;
    for (std::size_t i = 0; i < a.id.size(); ++i) in_a[a.id[i]] = i;
    for (std::size_t j = 0; j < b.id.size(); ++j) {
      const auto it = in_a.find(b.id[j]);
      if (it == in_a.end() || b.kind[j] != 0 || b.radius[j] >= large_radius) continue;
      const Vec2 mid = 0.5 * (a.position[it->second] + b.position[j]);
      if (mid.x < x0 || mid.x >= x1) continue;
      const auto bin = std::min(bins - 1, static_cast<std::size_t>((mid.x - x0) / w));
      sum[bin] += (b.position[j].y - a.position[it->second].y) / dt;
      ++c.count[bin];
    }
  }
  for (std::size_t k = 0; k < bins; ++k) {
    c.x.push_back(x0 + (static_cast<double>(k) + 0.5) * w);
    c.drift.push_back(c.count[k] ? sum[k] / static_cast<double>(c.count[k]) : 0.0);
  }
  return c;
}

} // namespace talus
