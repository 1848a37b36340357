#include "post/frost_cycles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "post/flow_profiles.hpp"
#include "talus/error.hpp"

namespace talus {

namespace {

// The stones (well above the median grain: 1.5 median radii, largest first) and the tracer
// fines, spread evenly in height from the bottom to the top, of the first frame. Returns the
// median radius.
double choose_grains(const Frame& first, std::size_t tracer_fines, FrostCycles& c) {
  std::vector<double> radii;
  for (std::size_t i = 0; i < first.radius.size(); ++i)
    if (first.kind[i] == 0) radii.push_back(first.radius[i]);
  if (radii.empty()) throw InvalidArgument("frost: the first snapshot has no free grains");
  std::sort(radii.begin(), radii.end());
  const double median = radii[radii.size() / 2];
  c.stone_radius = 1.5 * median;
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
  return median;
}

// The frames of the bed at rest: the last one before each freeze (and the run's end), or the
// first one when there are no freezes.
std::vector<std::size_t> rest_frames(const std::vector<Frame>& frames,
                                     const std::vector<double>& freeze_times) {
  std::vector<std::size_t> picks;
  if (freeze_times.empty()) picks.push_back(0);
  for (const double t : freeze_times) {
    std::size_t best = 0;
    for (std::size_t k = 0; k < frames.size(); ++k)
      if (frames[k].time < t * (1.0 - 1e-9)) best = k;
    picks.push_back(best);
  }
  return picks;
}

// The free grains' extent in a frame: lowest bottom and highest top, leftmost and rightmost edge.
struct BedExtent {
  double bottom = std::numeric_limits<double>::max(), top = -bottom;
  double x0 = std::numeric_limits<double>::max(), x1 = -x0;
};

BedExtent bed_extent(const Frame& f) {
  BedExtent e;
  for (std::size_t i = 0; i < f.id.size(); ++i)
    if (f.kind[i] == 0) {
      e.bottom = std::min(e.bottom, f.position[i].y - f.radius[i]);
      e.top = std::max(e.top, f.position[i].y + f.radius[i]);
      e.x0 = std::min(e.x0, f.position[i].x - f.radius[i]);
      e.x1 = std::max(e.x1, f.position[i].x + f.radius[i]);
    }
  return e;
}

// The top of the fines: the 95th percentile of their y + R (else the bed's top).
double fines_top(const Frame& f, double stone_radius, double bed_top) {
  std::vector<double> tops;
  for (std::size_t i = 0; i < f.id.size(); ++i)
    if (f.kind[i] == 0 && f.radius[i] < stone_radius) tops.push_back(f.position[i].y + f.radius[i]);
  std::sort(tops.begin(), tops.end());
  return tops.empty() ? bed_top : tops[tops.size() * 95 / 100];
}

// (mean stone height - mean fine height) / bed height; 0 without stones or fines.
double sorting_index(const Frame& f, double stone_radius, const BedExtent& e) {
  double ms = 0, mf = 0;
  std::size_t ns = 0, nf = 0;
  for (std::size_t i = 0; i < f.id.size(); ++i) {
    if (f.kind[i] != 0) continue;
    const double h = f.position[i].y - e.bottom;
    if (f.radius[i] >= stone_radius)
      ms += h, ++ns;
    else
      mf += h, ++nf;
  }
  return ns && nf && e.top > e.bottom
             ? (ms / static_cast<double>(ns) - mf / static_cast<double>(nf)) / (e.top - e.bottom)
             : 0.0;
}

// One cycle's measures of frame f into c: the heights, the bed, the sorting and the stones'
// surface cover (their top within two median fine diameters of the fines' top); at the first,
// each stone's starting depth too.
void measure_cycle(const Frame& f, double median, FrostCycles& c) {
  std::unordered_map<std::uint32_t, std::size_t> at;
  for (std::size_t i = 0; i < f.id.size(); ++i)
    if (f.kind[i] == 0) at[f.id[i]] = i;
  const BedExtent e = bed_extent(f);
  const auto height = [&](std::uint32_t id) {
    const auto it = at.find(id);
    return it == at.end() ? std::nan("") : f.position[it->second].y - e.bottom;
  };
  c.time.push_back(f.time);
  c.bed_height.push_back(e.top - e.bottom);
  std::vector<double> hs, hf;
  for (const auto id : c.stones) hs.push_back(height(id));
  for (const auto id : c.fines) hf.push_back(height(id));
  c.stone_height.push_back(hs);
  c.fine_height.push_back(hf);
  const double fine_top = fines_top(f, c.stone_radius, e.top);
  const double d_fine = 2.0 * median;
  double cover = 0.0;
  for (std::size_t i = 0; i < f.id.size(); ++i)
    if (f.kind[i] == 0 && f.radius[i] >= c.stone_radius &&
        f.position[i].y + f.radius[i] >= fine_top - 2.0 * d_fine)
      cover += 2.0 * f.radius[i];
  c.surface_cover.push_back(e.x1 > e.x0 ? cover / (e.x1 - e.x0) : 0.0);
  if (c.time.size() == 1)
    for (const auto id : c.stones) {
      const auto it = at.find(id);
      c.start_depth.push_back(it == at.end()
                                  ? std::nan("")
                                  : fine_top - f.position[it->second].y - f.radius[it->second]);
    }
  c.sorting_index.push_back(sorting_index(f, c.stone_radius, e));
}

} // namespace

FrostCycles frost_cycles(const std::vector<Frame>& frames, const std::vector<double>& freeze_times,
                         std::size_t tracer_fines) {
  if (frames.empty()) throw InvalidArgument("frost: the run has no snapshots");
  FrostCycles c;
  const double median = choose_grains(frames.front(), tracer_fines, c);
  for (const std::size_t k : rest_frames(frames, freeze_times)) measure_cycle(frames[k], median, c);
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
