// `talus analyze DIR segregation` and `frost`: where the large grains and the stones go.
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/core.h>

#include "cli/analyze/analyses.hpp"
#include "io/checkpoint.hpp"
#include "post/frost_cycles.hpp"
#include "post/segregation.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

std::vector<double> freeze_times(const fs::path& file) {
  std::ifstream in(file);
  if (!in)
    throw InvalidArgument(fmt::format("'{}' has no frost.csv: not a frost run ([frost] model)",
                                      file.parent_path().string()));
  std::string line;
  std::getline(in, line);
  std::vector<double> out;
  for (std::size_t n = 2; std::getline(in, line); ++n) {
    std::istringstream row(line);
    double cycle = 0, t = 0;
    char comma = 0;
    std::string event;
    if (!(row >> cycle >> comma >> t >> comma >> event))
      throw InvalidArgument(fmt::format("{}:{}: malformed row", file.string(), n));
    if (event == "freeze" || event == "end") out.push_back(t); // the bed at rest
  }
  return out;
}

Section analyze_segregation(RunData& run, const AnalysisOptions& o) {
  const auto& frames = run.frames(o.from);
  const SegregationSeries g = segregation(frames);
  const fs::path out = run.out();
  std::string csv = "time,bed_height,index,largest_depth_fraction";
  for (std::size_t k = 0; k < g.largest.size(); ++k) csv += fmt::format(",largest_{}_height", k);
  csv += "\n";
  for (std::size_t f = 0; f < g.time.size(); ++f) {
    csv += fmt::format("{:.6g},{:.6g},{:.6g},{}", g.time[f], g.bed_height[f], g.index[f],
                       csv_number(g.largest_depth_fraction[f]));
    for (const double h : g.largest_height[f]) csv += fmt::format(",{}", csv_number(h));
    csv += "\n";
  }
  write_file_atomically((out / "segregation.csv").string(), csv);

  const std::size_t bins = o.bins ? o.bins : 10;
  const ConvectionProfile c = convection(frames, g.large_radius, bins);
  std::string conv = "x,drift,samples\n";
  for (std::size_t b = 0; b < c.x.size(); ++b)
    conv += fmt::format("{:.6g},{:.6g},{}\n", c.x[b], c.drift[b], c.count[b]);
  write_file_atomically((out / "convection.csv").string(), conv);

  // the last quarter of the run: where the largest grain ends up, and how the small ones drift
  const std::size_t n = g.time.size(), tail = n - n / 4 - 1;
  double depth = 0, index = 0;
  std::size_t used = 0;
  for (std::size_t f = tail; f < n; ++f)
    if (std::isfinite(g.largest_depth_fraction[f]))
      depth += g.largest_depth_fraction[f], index += g.index[f], ++used;
  depth = used ? depth / static_cast<double>(used) : std::nan("");
  index = used ? index / static_cast<double>(used) : std::nan("");
  double wall_drift = 0, centre_drift = 0;
  if (c.x.size() >= 4) {
    wall_drift = 0.5 * (c.drift.front() + c.drift.back());
    const std::size_t mid = c.x.size() / 2;
    centre_drift = 0.5 * (c.drift[mid - 1] + c.drift[mid]);
  }
  const double w = c.x.size() > 1 ? c.x[1] - c.x[0] : 0.0;
  write_file_atomically(
      (out / "segregation.json").string(),
      fmt::format("{{\"large_radius\": {}, \"large_count\": {}, \"largest\": {}, "
                  "\"index_start\": {}, \"index_end\": {}, \"largest_depth_fraction_start\": {}, "
                  "\"largest_depth_fraction_end\": {}, \"wall_drift\": {}, \"centre_drift\": {}, "
                  "\"bin_width\": {}}}\n",
                  json_number(g.large_radius), g.large_count, g.largest.size(),
                  json_number(g.index.front()), json_number(index),
                  json_number(g.largest_depth_fraction.front()), json_number(depth),
                  json_number(wall_drift), json_number(centre_drift), json_number(w)));
  Section s{"Size segregation", {}, {}, {}};
  s.summary = fmt::format(
      "Grains with R >= {:.3g} mm count as large ({} of them). Heights are of centres above the "
      "bed's bottom; the index is (mean height of large - mean height of small) / bed height. "
      "End values: mean over the last quarter of the snapshots.",
      1e3 * g.large_radius, g.large_count);
  s.numbers = {
      {"segregation index, start and end", fmt::format("{:.3f}, {:.3f}", g.index.front(), index)},
      {"largest grain's depth below the top / bed height, start and end",
       fmt::format("{:.3f}, {:.3f}", g.largest_depth_fraction.front(), depth)},
      {"small grains' drift by the walls, at the centre",
       fmt::format("{:.3g}, {:.3g} m/s", wall_drift, centre_drift)}};
  fmt::print("segregation: index {:.3f} -> {:.3f}; largest grain from {:.2f} to {:.2f} of the bed "
             "height below the top; drift by the walls {:.3g} m/s, centre {:.3g} m/s\n",
             g.index.front(), index, g.largest_depth_fraction.front(), depth, wall_drift,
             centre_drift);
  if (plot(out, "segregation", out / "segregation.csv", out / "segregation.png",
           out / "segregation.json"))
    s.charts.push_back(out / "segregation.png");
  if (plot(out, "convection", out / "convection.csv", out / "convection.png",
           out / "segregation.json"))
    s.charts.push_back(out / "convection.png");
  for (const auto& chart : s.charts) fmt::print("  chart: {}\n", chart.string());
  return s;
}

Section analyze_frost(RunData& run) {
  const std::vector<double> freezes = freeze_times(run.dir() / "frost.csv");
  const FrostCycles c = frost_cycles(run.frames(0.0), freezes);
  const fs::path out = run.out();
  std::string csv = "cycle,time,id,role,radius,height\n";
  for (std::size_t k = 0; k < c.time.size(); ++k) {
    for (std::size_t s = 0; s < c.stones.size(); ++s)
      csv += fmt::format("{},{:.6g},{},stone,{:.6g},{}\n", k, c.time[k], c.stones[s],
                         c.stone_size[s], csv_number(c.stone_height[k][s]));
    for (std::size_t f = 0; f < c.fines.size(); ++f)
      csv += fmt::format("{},{:.6g},{},fine,,{}\n", k, c.time[k], c.fines[f],
                         csv_number(c.fine_height[k][f]));
  }
  write_file_atomically((out / "frost.csv").string(), csv);
  std::string cycles = "[", index = "[", cover = "[", rise = "[";
  for (std::size_t k = 0; k < c.time.size(); ++k) {
    const char* sep = k ? ", " : "";
    cycles += fmt::format("{}{}", sep, k);
    index += fmt::format("{}{}", sep, json_number(c.sorting_index[k]));
    cover += fmt::format("{}{}", sep, json_number(c.surface_cover[k]));
  }
  for (std::size_t s = 0; s < c.stones.size(); ++s)
    rise += fmt::format("{}{{\"id\": {}, \"radius\": {}, \"start_depth\": {}, "
                        "\"rise_per_cycle\": {}}}",
                        s ? ", " : "", c.stones[s], json_number(c.stone_size[s]),
                        json_number(c.start_depth[s]), json_number(c.rise_per_cycle[s]));
  write_file_atomically(
      (out / "frost.json").string(),
      fmt::format("{{\"freezes\": {}, \"stone_radius\": {}, \"cycles\": {}], "
                  "\"sorting_index\": {}], \"surface_cover\": {}], \"stones\": {}]}}\n",
                  c.time.size(), json_number(c.stone_radius), cycles, index, cover, rise));
  Section s{"Frost heave, cycle by cycle", {}, {}, {}};
  s.summary = fmt::format(
      "{} samples of the bed at rest (frost.csv: before each freeze, and at the end). Heights of "
      "the stones (R >= {:.3g} mm) and of {} tracer fines; sorting index (mean stone height - "
      "mean fine height) / bed height; surface stone cover: the share of the bed's width taken "
      "by stones at the surface.",
      c.time.size(), 1e3 * c.stone_radius, c.fines.size());
  fmt::print("frost: {} samples at rest (before each freeze, and the end), {} stones\n",
             c.time.size(), c.stones.size());
  for (std::size_t k = 0; k < c.stones.size(); ++k) {
    s.numbers.emplace_back(
        fmt::format("stone {} (R = {:.3g} mm): rise per cycle", c.stones[k], 1e3 * c.stone_size[k]),
        fmt::format("{:.3g} mm", 1e3 * c.rise_per_cycle[k]));
    fmt::print("  stone {} (R = {:.3g} mm): {:.3g} mm per cycle\n", c.stones[k],
               1e3 * c.stone_size[k], 1e3 * c.rise_per_cycle[k]);
  }
  s.numbers.emplace_back(
      "sorting index, start and end",
      fmt::format("{:.3f}, {:.3f}", c.sorting_index.front(), c.sorting_index.back()));
  if (plot(out, "frost", out / "frost.csv", out / "frost.png", out / "frost.json")) {
    s.charts.push_back(out / "frost.png");
    fmt::print("  chart: {}\n", (out / "frost.png").string());
  }
  return s;
}

} // namespace talus::cli
