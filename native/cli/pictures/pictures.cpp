#include "cli/pictures/pictures.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <stdexcept>

#include <fmt/core.h>

#include "io/track_csv.hpp"
#include "io/vtp_reader.hpp"
#include "render/snapshot_png.hpp"
#include "talus/error.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

// One scale for a whole series: the union of the frames' extents, the range of the colour field.
PictureOptions series_options(const std::vector<Snapshot>& shots,
                              const std::vector<std::size_t>& picks, int width,
                              SnapshotColour colour, bool chains) {
  PictureOptions o{width, colour, {}, {}, chains, {}, {}};
  double f_max = 0.0;
  Rect box = frame_bounds(load_snapshot(shots[picks.front()]));
  double lo = 1e300, hi = 0.0;
  for (const std::size_t k : picks) {
    const Frame f = load_snapshot(shots[k]);
    const Rect b = frame_bounds(f);
    box = {{std::min(box.lo.x, b.lo.x), std::min(box.lo.y, b.lo.y)},
           {std::max(box.hi.x, b.hi.x), std::max(box.hi.y, b.hi.y)}};
    for (std::size_t i = 0; i < f.radius.size(); ++i) {
      if (f.kind[i] != 0) continue;
      const double v = colour == SnapshotColour::speed   ? norm(f.velocity[i])
                       : colour == SnapshotColour::force ? norm(f.force[i])
                                                         : f.radius[i];
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
    for (const auto& ch : f.chains) f_max = std::max(f_max, ch.force);
  }
  o.bounds = box;
  if (chains && f_max > 0.0) o.chain_scale = f_max;
  if (hi > lo) o.range = std::pair{lo, hi};
  return o;
}

using Tracks = std::map<std::uint32_t, std::vector<TrackPoint>>;

Tracks tracks_of(const fs::path& dir) {
  const fs::path csv = dir / "track.csv";
  if (!fs::exists(csv))
    throw InvalidArgument(
        "'" + dir.string() +
        "' has no track.csv: the scenario tracks no particles (set "
        "[track] ids = [...] or select = \"largest\", \"smallest\", \"nearest\")");
  return read_tracks(csv.string());
}

// The paths up to time t (a little slack for rounding in the written times).
std::vector<TrackLine> lines_until(const Tracks& tracks, double t) {
  std::vector<TrackLine> out;
  for (const auto& [id, points] : tracks) {
    TrackLine line{id, {}};
    for (std::size_t k = 0; k < points.size(); ++k) {
      const TrackPoint& p = points[k];
      if (p.time > t * (1.0 + 1e-9) + 1e-12) break;
      // across a periodic boundary the path goes on from the other side: no line across the box
      if (k > 0 &&
          norm((p.position - points[k - 1].position) - (p.unwrapped - points[k - 1].unwrapped)) >
              1e-9 * (1.0 + norm(p.unwrapped))) {
        out.push_back(std::move(line));
        line = TrackLine{id, {}};
      }
      line.points.push_back(p.position);
    }
    out.push_back(std::move(line));
  }
  return out;
}

} // namespace

std::vector<Snapshot> snapshots_of(const fs::path& dir) {
  const fs::path pvd = dir / "particles.pvd";
  if (!fs::exists(pvd))
    throw InvalidArgument("'" + dir.string() +
                          "' has no particles.pvd: not a talus run folder, "
                          "or a run with output.snapshot_interval = 0");
  std::vector<Snapshot> out;
  for (const auto& [t, file] : read_pvd(pvd.string())) {
    std::string walls = file, contacts = file;
    if (const auto k = file.find("particles_"); k != std::string::npos) {
      walls.replace(k, 10, "walls_");
      contacts.replace(k, 10, "contacts_");
    } else if (const auto s = file.find("spheres_"); s != std::string::npos) { // a 3D run's
      walls.replace(s, 8, "plates_");
      contacts.replace(s, 8, "contacts_");
    }
    out.push_back({t, dir / file, dir / walls, dir / contacts});
  }
  if (out.empty()) throw InvalidArgument(pvd.string() + " lists no snapshots");
  return out;
}

Frame load_snapshot(const Snapshot& s) {
  return read_vtp_frame(s.particles.string(), s.walls.string(), s.time, s.contacts.string());
}

std::vector<std::size_t> pick_frames(const std::string& which, std::size_t n) {
  std::vector<std::size_t> picks;
  if (which == "all") {
    for (std::size_t k = 0; k < n; ++k) picks.push_back(k);
  } else if (which == "last") {
    picks.push_back(n - 1);
  } else {
    std::size_t k = 0;
    try {
      std::size_t used = 0;
      k = std::stoul(which, &used);
      if (used != which.size()) throw std::invalid_argument(which);
    } catch (...) {
      throw InvalidArgument("--frames '" + which + "': allowed: all, last, or a snapshot number");
    }
    if (k >= n)
      throw InvalidArgument("--frames " + which + ": the run has snapshots 0 to " +
                            std::to_string(n - 1));
    picks.push_back(k);
  }
  return picks;
}

std::size_t render_run(const fs::path& dir, const PictureRequest& r, const std::string& frames,
                       int width, const fs::path& out) {
  const auto shots = snapshots_of(dir);
  const auto picks = pick_frames(frames, shots.size());
  const Tracks tracks = r.tracks ? tracks_of(dir) : Tracks{};
  PictureOptions opts = series_options(shots, picks, width, parse_colour(r.colour), r.chains);
  fs::create_directories(out);
  for (const std::size_t k : picks) {
    if (r.tracks) opts.tracks = lines_until(tracks, shots[k].time);
    write_frame_png(load_snapshot(shots[k]),
                    (out / fmt::format("{}_{:06d}.png", picture_stem(r), k)).string(), opts);
  }
  return picks.size();
}

std::size_t make_movie(const fs::path& dir, const PictureRequest& r, double fps, int width) {
  if (std::system("command -v ffmpeg > /dev/null 2>&1") != 0)
    throw InvalidArgument("a movie needs ffmpeg (apt-get install ffmpeg)");
  const fs::path frames = dir / "movie_frames";
  fs::remove_all(frames);
  const std::size_t n = render_run(dir, r, "all", width, frames);
  const fs::path mp4 = dir / "movie.mp4", partial = dir / "movie.partial.mp4";
  const std::string cmd = fmt::format(
      "ffmpeg -y -loglevel error -framerate {} -i '{}/{}_%06d.png' -c:v libx264 -pix_fmt "
      "yuv420p -f mp4 '{}'",
      fps, frames.string(), picture_stem(r), partial.string());
  const bool ok = std::system(cmd.c_str()) == 0;
  fs::remove_all(frames);
  if (!ok) {
    fs::remove(partial);
    throw std::runtime_error("ffmpeg failed: " + cmd);
  }
  fs::rename(partial, mp4);
  return n;
}

} // namespace talus::cli
