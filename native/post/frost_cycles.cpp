#include "post/frost_cycles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "post/flow_profiles.hpp"
#include "talus/error.hpp"

namespace talus {

FrostCycles frost_cycles(const std::vector<Frame>& frames, const std::vector<double>& freeze_times,
                         std::size_t tracer_fines) {
  if (frames.empty()) throw InvalidArgument("frost: the run has no snapshots");
  FrostCycles c;
  const Frame& first = frames.front();
  std::vector<double> radii;
  for (std::size_t i = 0; i < first.radius.size(); ++i)
    if (first.kind[i] == 0) radii.push_back(first.radius[i]);
  if (radii.empty()) throw InvalidArgument("frost: the first snapshot has no free grains");
  std::vector<double> sorted = radii;
  std::sort(sorted.begin(), sorted.end());
  c.stone_radius = 1.5 * sorted[sorted.size() / 2]; // stones: well above the median grain
  std::vector<std::pair<double, std::uint32_t>> stones;
  std::vector<std::pair<double, std::uint32_t>> fines; // by height
  for (std::size_t i = 0; i < first.radius.size(); ++i) {
    if (first.kind[i] != 0) continue;
    if (first.radius[i] >= c.stone_radius)
      stones.emplace_back(first.radius[i], first.id[i]);
    else
      fines.emplace_back(first.position[i].y, first.id[i]);
  }
  std::sort(stones.begin(), stones.end(), [](auto a, auto b) { return a.first > b.first; });
  for (const auto& [r, id] : stones) c.stones.push_back(id), c.stone_size.push_back(r);
  std::sort(fines.begin(), fines.end());
  const std::size_t nf = std::min(tracer_fines, fines.size());
  for (std::size_t k = 0; k < nf; ++k) // evenly from the bottom (k = 0) to the top
    c.fines.push_back(fines[nf > 1 ? k * (fines.size() - 1) / (nf - 1) : 0].second);

  std::vector<std::size_t> picks; // the bed at rest before each freeze (and at the end)
  if (freeze_times.empty()) picks.push_back(0);
  for (const double t : freeze_times) {
    std::size_t best = 0;
    for (std::size_t k = 0; k < frames.size(); ++k)
      if (frames[k].time < t * (1.0 - 1e-9)) best = k;
    picks.push_back(best);
  }
  for (const std::size_t k : picks) {
    const Frame& f = frames[k];
    std::unordered_map<std::uint32_t, std::size_t> at;
    double bottom = std::numeric_limits<double>::max(), top = -bottom;
    for (std::size_t i = 0; i < f.id.size(); ++i)
      if (f.kind[i] == 0) {
        at[f.id[i]] = i;
        bottom = std::min(bottom, f.position[i].y - f.radius[i]);
        top = std::max(top, f.position[i].y + f.radius[i]);
      }
    const auto height = [&](std::uint32_t id) {
      const auto it = at.find(id);
      return it == at.end() ? std::nan("") : f.position[it->second].y - bottom;
    };
    c.time.push_back(f.time);
    c.bed_height.push_back(top - bottom);
    std::vector<double> hs, hf;
    for (const auto id : c.stones) hs.push_back(height(id));
    for (const auto id : c.fines) hf.push_back(height(id));
    c.stone_height.push_back(hs);
    c.fine_height.push_back(hf);
    double ms = 0, mf = 0;
    std::size_t ns = 0, n_f = 0;
    for (std::size_t i = 0; i < f.id.size(); ++i) {
      if (f.kind[i] != 0) continue;
      const double h = f.position[i].y - bottom;
      if (f.radius[i] >= c.stone_radius)
        ms += h, ++ns;
      else
        mf += h, ++n_f;
    }
    // stones at the surface: the top of the fines is their 95th percentile of y + R
    std::vector<double> fine_tops;
    double x0 = std::numeric_limits<double>::max(), x1 = -x0;
    for (std::size_t i = 0; i < f.id.size(); ++i)
      if (f.kind[i] == 0) {
        x0 = std::min(x0, f.position[i].x - f.radius[i]);
        x1 = std::max(x1, f.position[i].x + f.radius[i]);
        if (f.radius[i] < c.stone_radius) fine_tops.push_back(f.position[i].y + f.radius[i]);
      }
    std::sort(fine_tops.begin(), fine_tops.end());
    const double fine_top = fine_tops.empty() ? top : fine_tops[fine_tops.size() * 95 / 100];
    const double d_fine = 2.0 * sorted[sorted.size() / 2];
    double cover = 0.0;
    for (std::size_t i = 0; i < f.id.size(); ++i)
      if (f.kind[i] == 0 && f.radius[i] >= c.stone_radius &&
          f.position[i].y + f.radius[i] >= fine_top - 2.0 * d_fine)
        cover += 2.0 * f.radius[i];
    c.surface_cover.push_back(x1 > x0 ? cover / (x1 - x0) : 0.0);
    if (c.time.size() == 1)
      for (const auto id : c.stones) {
        const auto it = at.find(id);
        c.start_depth.push_back(it == at.end()
                                    ? std::nan("")
                                    : fine_top - f.position[it->second].y - f.radius[it->second]);
      }
    c.sorting_index.push_back(ns && n_f && top > bottom
                                  ? (ms / static_cast<double>(ns) - mf / static_cast<double>(n_f)) /
                                        (top - bottom)
                                  : 0.0);
  }
  std::vector<double> cycle;
  for (std::size_t k = 0; k < c.time.size(); ++k) cycle.push_back(static_cast<double>(k));
  for (std::size_t s = 0; s < c.stones.size(); ++s) {
    std::vector<double> h;
    for (const auto& row : c.stone_height) h.push_back(row[s]);
    c.rise_per_cycle.push_back(slope(cycle, h));
  }
  return c;
}

} // namespace talus
