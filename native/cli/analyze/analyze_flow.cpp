// `talus analyze DIR profiles` and `tracks`: velocity profiles across a band, the false-colour
// speed map, the discharge through an orifice, and the tracked particles against time.
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/core.h>

#include "cli/analyze/analyses.hpp"
#include "io/checkpoint.hpp"
#include "io/track_csv.hpp"
#include "post/coarse_grain.hpp"
#include "post/discharge.hpp"
#include "post/flow_profiles.hpp"
#include "scenario/geometry.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

bool has_orifice(const Scenario& s) {
  return talus::has_orifice(s.geometry);
}

// Grows r to take in the free grains of a frame.
void take_in(Rect& r, const Frame& f) {
  for (std::size_t i = 0; i < f.position.size(); ++i) {
    if (f.kind[i] != 0) continue;
    r.lo = {std::min(r.lo.x, f.position[i].x - f.radius[i]),
            std::min(r.lo.y, f.position[i].y - f.radius[i])};
    r.hi = {std::max(r.hi.x, f.position[i].x + f.radius[i]),
            std::max(r.hi.y, f.position[i].y + f.radius[i])};
  }
}

constexpr Rect empty_rect{
    {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()},
    {std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()}};

} // namespace

Discharge run_discharge(RunData& run, const AnalysisOptions& o) {
  const GeometrySection& g = run.scenario().geometry;
  if (!talus::has_orifice(g))
    throw InvalidArgument("'" + run.dir().string() + "' has no orifice (builder '" + g.builder +
                          "'): a discharge needs a hopper, an hourglass or a silo with an orifice");
  const auto [x0, x1] = orifice_span(g);
  DischargeOptions d;
  d.window = o.window;
  return discharge(run.frames(o.from), Orifice{0.0, x0, x1}, d);
}

std::string discharge_text(const Discharge& q) {
  if (!q.why_no_rate.empty())
    return fmt::format("no rate: {} ({} grains through in all)", q.why_no_rate, q.passed);
  return fmt::format("{:.4g} +- {:.2g} grains/s over t = {:.4g} to {:.4g} s ({} window; halves "
                     "{:.4g}, {:.4g}); {} grains through, {} at the end",
                     q.rate, q.rate_error, q.window_from, q.window_to,
                     q.window_given ? "given" : "steady", q.rate_first_half, q.rate_second_half,
                     q.passed, to_string(q.end));
}

void write_discharge(const fs::path& out, const Discharge& q) {
  std::string dc = "time,grains_below\n";
  for (std::size_t k = 0; k < q.time.size(); ++k)
    dc += fmt::format("{:.6g},{}\n", q.time[k], q.below[k]);
  write_file_atomically((out / "discharge.csv").string(), dc);
  std::string blocks;
  for (const FlowBlock& b : q.blocks)
    blocks += fmt::format("{}[{}, {}, {}]", blocks.empty() ? "" : ", ", json_number(b.from),
                          json_number(b.to), json_number(b.rate));
  std::string json = fmt::format(
      "{{\"end\": \"{}\", \"passed\": {}, \"first_passage\": {}, \"last_passage\": {}, "
      "\"rate\": {}, \"rate_error\": {}, \"intercept\": {}, \"window\": \"{}\", "
      "\"window_from\": {}, \"window_to\": {}, \"rate_first_half\": {}, "
      "\"rate_second_half\": {}, \"median_block_rate\": {}, \"blocks\": [{}]",
      to_string(q.end), q.passed, json_number(q.first_passage), json_number(q.last_passage),
      json_number(q.rate), json_number(q.rate_error), json_number(q.intercept),
      q.window_given ? "given" : "steady", json_number(q.window_from), json_number(q.window_to),
      json_number(q.rate_first_half), json_number(q.rate_second_half), json_number(q.median_rate),
      blocks);
  json.append(", \"why_no_rate\": ");
  json.append(q.why_no_rate.empty() ? "null" : "\"" + q.why_no_rate + "\"");
  write_file_atomically((out / "discharge.json").string(), json + "}\n");
}

namespace {

// The band of the velocity profile, [x0, x1) x [y0, y1): given, or just above the orifice (2
// orifice widths high), or the middle fifth of the bed at the start across where the grains went.
Rect profile_band(const Scenario& sc, const std::vector<Frame>& frames, const Rect& seen,
                  const AnalysisOptions& o) {
  double y0 = 0.0, y1 = 0.0, x0 = seen.lo.x, x1 = seen.hi.x;
  if (o.band) {
    std::tie(y0, y1) = *o.band;
  } else if (has_orifice(sc)) {
    y0 = 0.0, y1 = 2.0 * sc.geometry.orifice;
    x0 = 0.0, x1 = sc.geometry.width;
  } else {
    Rect start = empty_rect;
    take_in(start, frames.front());
    y0 = start.lo.y + 0.4 * (start.hi.y - start.lo.y);
    y1 = start.lo.y + 0.6 * (start.hi.y - start.lo.y);
  }
  return {{x0, y0}, {x1, y1}};
}

// v_y on the centre line and in the outermost occupied bins (their mean): the thesis' funnel
// flow (fig. 4.7). NaN when no bin holds a grain.
std::pair<double, double> centre_and_edges(const BandProfile& p, double x0, double x1) {
  const std::size_t bins = p.x.size();
  std::size_t first = bins, last = 0;
  for (std::size_t b = 0; b < bins; ++b)
    if (p.count[b] > 0) first = std::min(first, b), last = std::max(last, b);
  if (first > last) return {std::nan(""), std::nan("")};
  const double mid = 0.5 * (x0 + x1);
  std::size_t c = first;
  for (std::size_t b = first; b <= last; ++b)
    if (p.count[b] > 0 && std::abs(p.x[b] - mid) < std::abs(p.x[c] - mid)) c = b;
  return {p.vy[c], 0.5 * (p.vy[first] + p.vy[last])};
}

// The mean speed on a grid of `cell` over where the grains went: speed_map.csv and .json.
void write_speed_map(const fs::path& out, const std::vector<Frame>& frames, const Rect& seen,
                     double cell) {
  const SpeedMap m = speed_map(frames, seen, cell);
  std::string map = "column,row,x,y,mean_speed,samples\n";
  for (std::size_t r = 0; r < m.ny; ++r)
    for (std::size_t c = 0; c < m.nx; ++c)
      map += fmt::format("{},{},{:.6g},{:.6g},{:.6g},{}\n", c, r,
                         m.region.lo.x + (static_cast<double>(c) + 0.5) * cell,
                         m.region.lo.y + (static_cast<double>(r) + 0.5) * cell,
                         m.mean_speed[r * m.nx + c], m.count[r * m.nx + c]);
  write_file_atomically((out / "speed_map.csv").string(), map);
  write_file_atomically(
      (out / "speed_map.json").string(),
      fmt::format("{{\"nx\": {}, \"ny\": {}, \"cell\": {}, \"region\": [{}, {}, {}, {}], "
                  "\"snapshots\": {}}}\n",
                  m.nx, m.ny, json_number(cell), json_number(m.region.lo.x),
                  json_number(m.region.lo.y), json_number(m.region.hi.x),
                  json_number(m.region.hi.y), frames.size()));
}

} // namespace

double start_up_end(RunData& run) {
  const auto& all = run.frames(0.0);
  return all.empty() ? 0.0 : all.front().time + 0.25 * (all.back().time - all.front().time);
}

double steady_from(RunData& run, const AnalysisOptions& a) {
  if (a.from >= 0.0) return a.from;
  const std::vector<Frame>& all = run.frames(0.0);
  return 0.5 * (all.front().time + all.back().time);
}

double kernel_width(RunData& run, const AnalysisOptions& a) {
  if (a.width > 0.0) return a.width;
  return (parse_cg_kernel(a.kernel) == CgKernel::lucy ? 2.0 : 1.0) * run.mean_radius();
}

Section analyze_profiles(RunData& run, const AnalysisOptions& o) {
  const Scenario& sc = run.scenario();
  // a flow kept going (an orifice, a turning drum, a driven wall) has a start-up before its
  // steady state; a bed that settles, heaves or is pressed has none to leave out
  const bool driven_flow =
      has_orifice(sc) || sc.geometry.angular_velocity != 0.0 || !sc.drivers.empty();
  const bool start_up_left_out = o.from < 0.0 && driven_flow;
  const double from = start_up_left_out ? start_up_end(run) : std::max(0.0, o.from);
  const auto& frames = run.frames(from);
  const double d = 2.0 * run.mean_radius();
  Rect seen = empty_rect; // where the grains went, over all frames
  for (const Frame& f : frames) take_in(seen, f);
  const Rect band = profile_band(sc, frames, seen, o);
  const double y0 = band.lo.y, y1 = band.hi.y, x0 = band.lo.x, x1 = band.hi.x;
  const double across = (x1 - x0) / d; // no grain left in the frames: not a number
  const std::size_t bins =
      o.bins
          ? o.bins
          : static_cast<std::size_t>(std::isfinite(across) ? std::clamp(across, 5.0, 60.0) : 5.0);
  const BandProfile p = band_profile(frames, y0, y1, x0, x1, bins);
  const fs::path out = run.out();
  std::string csv = "x,vx,vy,speed,samples\n";
  for (std::size_t b = 0; b < p.x.size(); ++b)
    csv += fmt::format("{:.6g},{:.6g},{:.6g},{:.6g},{}\n", p.x[b], p.vx[b], p.vy[b], p.speed[b],
                       p.count[b]);
  write_file_atomically((out / "profiles.csv").string(), csv);
  const auto [centre, edges] = centre_and_edges(p, x0, x1);

  Section s{"Velocity profiles and speed map", {}, {}, {}};
  s.summary = fmt::format("Mean velocity of the grains in the band {:.4g} m <= y < {:.4g} m, in {} "
                          "bins across x, over {} snapshots from t = {:.3g} s; the mean speed on a "
                          "grid (false colour).",
                          y0, y1, bins, frames.size(), frames.front().time);
  s.numbers = {{"v_y on the centre line", fmt::format("{:.4g} m/s", centre)},
               {"v_y in the outermost occupied bins", fmt::format("{:.4g} m/s", edges)}};
  std::string json = fmt::format(
      "{{\"band\": [{}, {}], \"bins\": {}, \"snapshots\": {}, \"from\": {}, \"centre_vy\": {}, "
      "\"edge_vy\": {}",
      json_number(y0), json_number(y1), bins, frames.size(), json_number(frames.front().time),
      json_number(centre), json_number(edges));
  fmt::print("profiles: band {:.4g} to {:.4g} m, {} bins, {} snapshots from t = {:.3g} s{}; v_y "
             "centre {:.4g} m/s, edges {:.4g} m/s\n",
             y0, y1, bins, frames.size(), frames.front().time,
             start_up_left_out ? " (the first quarter of the run left out as its start-up; "
                                 "--from T sets where to start)"
                               : "",
             centre, edges);
  // cells of two mean diameters by default
  write_speed_map(out, frames, seen, o.cell > 0.0 ? o.cell : 2.0 * d);

  if (has_orifice(sc)) {
    const Discharge q = run_discharge(run, o);
    write_discharge(out, q);
    s.numbers.emplace_back("discharge", discharge_text(q));
    fmt::print("  discharge: {}\n", discharge_text(q));
  }
  write_file_atomically((out / "profiles.json").string(), json + "}\n");
  if (plot(out, "profiles", out / "profiles.csv", out / "profiles.png", out / "profiles.json"))
    s.charts.push_back(out / "profiles.png");
  if (plot(out, "speed_map", out / "speed_map.csv", out / "speed_map.png", out / "speed_map.json"))
    s.charts.push_back(out / "speed_map.png");
  if (has_orifice(sc) &&
      plot(out, "discharge", out / "discharge.csv", out / "discharge.png", out / "discharge.json"))
    s.charts.push_back(out / "discharge.png");
  for (const auto& c : s.charts) fmt::print("  chart: {}\n", c.string());
  return s;
}

Section analyze_tracks(RunData& run) {
  const fs::path track = run.dir() / "track.csv";
  if (!fs::exists(track))
    throw InvalidArgument("'" + run.dir().string() +
                          "' has no track.csv: the scenario tracks no particles");
  const auto tracks = read_tracks(track.string());
  std::string csv = "time,id,x,y,vx,vy,speed,xu,yu\n";
  Section s{"Tracked particles", {}, {}, {}};
  s.summary = "Positions and velocities of the tracked particles against time (track.csv); "
              "across periodic boundaries the positions are unwrapped.";
  std::string json = "{\"tracks\": [";
  for (const auto& [id, points] : tracks) {
    double path = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const TrackPoint& p = points[k];
      csv += fmt::format("{:.9g},{},{:.9g},{:.9g},{:.6g},{:.6g},{:.6g},{:.9g},{:.9g}\n", p.time, id,
                         p.position.x, p.position.y, p.velocity.x, p.velocity.y, norm(p.velocity),
                         p.unwrapped.x, p.unwrapped.y);
      // unwrapped: a grain that crossed a periodic boundary went on, it did not jump back
      if (k) path += norm(p.unwrapped - points[k - 1].unwrapped);
    }
    const Vec2 net = points.back().unwrapped - points.front().unwrapped;
    const double span = points.back().time - points.front().time;
    json += fmt::format("{}{{\"id\": {}, \"path_length\": {}, \"displacement\": [{}, {}], "
                        "\"mean_speed\": {}}}",
                        json.back() == '[' ? "" : ", ", id, json_number(path), json_number(net.x),
                        json_number(net.y), json_number(span > 0.0 ? path / span : 0.0));
    s.numbers.emplace_back(fmt::format("particle {}: path, net (dx, dy)", id),
                           fmt::format("{:.4g} m, ({:.4g}, {:.4g}) m", path, net.x, net.y));
  }
  write_file_atomically((run.out() / "tracks.csv").string(), csv);
  write_file_atomically((run.out() / "tracks.json").string(), json + "]}\n");
  fmt::print("tracks: {} particle(s)\n", tracks.size());
  if (plot(run.out(), "tracks", run.out() / "tracks.csv", run.out() / "tracks.png")) {
    s.charts.push_back(run.out() / "tracks.png");
    fmt::print("  chart: {}\n", (run.out() / "tracks.png").string());
  }
  return s;
}

} // namespace talus::cli
