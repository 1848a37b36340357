// `talus render DIR` and `talus movie DIR`: pictures and a movie from a run folder's snapshots.
#include <cstdlib>
#include <filesystem>
#include <memory>

#include <fmt/core.h>

#include "cli/commands.hpp"
#include "core/error.hpp"
#include "io/vtp_reader.hpp"
#include "render/snapshot_png.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

namespace {

struct Snapshot {
  double time;
  fs::path particles;
  fs::path walls;
  fs::path contacts;
};

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
    }
    out.push_back({t, dir / file, dir / walls, dir / contacts});
  }
  if (out.empty()) throw InvalidArgument(pvd.string() + " lists no snapshots");
  return out;
}

Frame load(const Snapshot& s) {
  return read_vtp_frame(s.particles.string(), s.walls.string(), s.time, s.contacts.string());
}

// One scale for a whole series: the union of the frames' extents, the range of the colour field.
PictureOptions series_options(const std::vector<Snapshot>& shots,
                              const std::vector<std::size_t>& picks, int width,
                              SnapshotColour colour, bool chains) {
  PictureOptions o{width, colour, {}, {}, chains, {}};
  double f_max = 0.0;
  Rect box = frame_bounds(load(shots[picks.front()]));
  double lo = 1e300, hi = 0.0;
  for (const std::size_t k : picks) {
    const Frame f = load(shots[k]);
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

std::vector<std::size_t> pick_frames(const std::string& which, std::size_t n) {
  std::vector<std::size_t> picks;
  if (which == "all") {
    for (std::size_t k = 0; k < n; ++k) picks.push_back(k);
  } else if (which == "last") {
    picks.push_back(n - 1);
  } else {
    std::size_t k = 0;
    try {
      k = std::stoul(which);
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

} // namespace

void add_picture_commands(CLI::App& app) {
  struct Options {
    std::string dir, colour = "speed", frames = "last", out;
    int width = 1200;
    double fps = 10.0;
    bool chains = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* render = app.add_subcommand("render", "PNG pictures of a run's snapshots");
  render->add_option("dir", o->dir, "the run folder")->required()->check(CLI::ExistingDirectory);
  render->add_option("--color", o->colour, "speed, size, force, kind or material")
      ->capture_default_str();
  render->add_option("--frames", o->frames, "all, last, or a snapshot number")
      ->capture_default_str();
  render->add_option("--width", o->width, "picture width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(200, 8000));
  render->add_option("--out", o->out, "folder for the pictures (default: DIR/pictures)");
  render->add_flag("--chains", o->chains,
                   "force chains: contacts as lines, width and colour by force");
  render->callback([o] {
    const fs::path dir(o->dir);
    const auto shots = snapshots_of(dir);
    const auto picks = pick_frames(o->frames, shots.size());
    const PictureOptions opts =
        series_options(shots, picks, o->width, parse_colour(o->colour), o->chains);
    const fs::path out = o->out.empty() ? dir / "pictures" : fs::path(o->out);
    fs::create_directories(out);
    for (const std::size_t k : picks) {
      const fs::path png =
          out / fmt::format("{}{}_{:06d}.png", o->colour, o->chains ? "_chains" : "", k);
      write_frame_png(load(shots[k]), png.string(), opts);
    }
    fmt::print("wrote {} picture(s) to {}\n", picks.size(), out.string());
  });

  CLI::App* movie = app.add_subcommand("movie", "an MP4 movie of a run's snapshots (ffmpeg)");
  movie->add_option("dir", o->dir, "the run folder")->required()->check(CLI::ExistingDirectory);
  movie->add_option("--color", o->colour, "speed, size, force, kind or material")
      ->capture_default_str();
  movie->add_option("--fps", o->fps, "frames per second of the movie")->capture_default_str();
  movie->add_option("--width", o->width, "frame width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(200, 8000));
  movie->callback([o] {
    if (std::system("command -v ffmpeg > /dev/null 2>&1") != 0)
      throw InvalidArgument("talus movie needs ffmpeg (apt-get install ffmpeg)");
    const fs::path dir(o->dir);
    const auto shots = snapshots_of(dir);
    const auto picks = pick_frames("all", shots.size());
    const PictureOptions opts =
        series_options(shots, picks, o->width, parse_colour(o->colour), o->chains);
    const fs::path frames = dir / "movie_frames";
    fs::create_directories(frames);
    for (const std::size_t k : picks)
      write_frame_png(load(shots[k]), (frames / fmt::format("frame_{:06d}.png", k)).string(), opts);
    const fs::path mp4 = dir / "movie.mp4";
    const std::string cmd = fmt::format(
        "ffmpeg -y -loglevel error -framerate {} -i '{}/frame_%06d.png' -c:v libx264 -pix_fmt "
        "yuv420p '{}'",
        o->fps, frames.string(), mp4.string());
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("ffmpeg failed: " + cmd);
    fs::remove_all(frames);
    fmt::print("wrote {} ({} frames, {} per second)\n", mp4.string(), picks.size(), o->fps);
  });
}

} // namespace talus::cli
