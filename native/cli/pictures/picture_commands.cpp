// `talus render DIR` and `talus movie DIR`: pictures and a movie from a run folder's snapshots.
#include <filesystem>
#include <memory>

#include <fmt/core.h>

#include "cli/commands.hpp"
#include "cli/pictures/pictures.hpp"
#include "cli/run/run3d.hpp"

namespace fs = std::filesystem;

namespace talus::cli {

void add_picture_commands(CLI::App& app) {
  struct Options {
    std::string dir, colour = "speed", frames = "last", out;
    int width = 1200;
    double fps = 10.0;
    bool chains = false, tracks = false;
  };
  auto o = std::make_shared<Options>();
  const auto colours = CLI::IsMember({"speed", "size", "force", "kind", "material"});
  CLI::App* render = app.add_subcommand("render", "PNG pictures of a run's snapshots");
  render->add_option("dir", o->dir, "the run folder")->required()->check(CLI::ExistingDirectory);
  render->add_option("--color", o->colour, "speed, size, force, kind or material")
      ->capture_default_str()
      ->check(colours);
  render->add_option("--frames", o->frames, "all, last, or a snapshot number")
      ->capture_default_str();
  render->add_option("--width", o->width, "picture width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(200, 8000));
  render->add_option("--out", o->out, "folder for the pictures (default: DIR/pictures)");
  render->add_flag("--chains", o->chains,
                   "force chains: contacts as lines, width and colour by force");
  render->add_flag("--tracks", o->tracks,
                   "trajectories of the tracked particles (track.csv) up to each frame");
  render->callback([o] {
    const fs::path dir(o->dir);
    refuse_3d_run_folder(dir, "render");
    const fs::path out = o->out.empty() ? dir / "pictures" : fs::path(o->out);
    const std::size_t n =
        render_run(dir, {o->colour, o->chains, o->tracks}, o->frames, o->width, out);
    fmt::print("wrote {} picture(s) to {}\n", n, out.string());
  });

  CLI::App* movie = app.add_subcommand(
      "movie", "an MP4 movie of a run's snapshots (ffmpeg), time stamped on each frame");
  movie->add_option("dir", o->dir, "the run folder")->required()->check(CLI::ExistingDirectory);
  movie->add_option("--color", o->colour, "speed, size, force, kind or material")
      ->capture_default_str()
      ->check(colours);
  movie->add_option("--fps", o->fps, "frames per second of the movie")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 240.0));
  movie->add_option("--width", o->width, "frame width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(200, 8000));
  movie->add_flag("--chains", o->chains, "force chains on every frame");
  movie->add_flag("--tracks", o->tracks, "trajectories of the tracked particles");
  movie->callback([o] {
    const fs::path dir(o->dir);
    refuse_3d_run_folder(dir, "movie");
    const std::size_t n = make_movie(dir, {o->colour, o->chains, o->tracks}, o->fps, o->width);
    fmt::print("wrote {} ({} frames, {} per second)\n", (dir / "movie.mp4").string(), n, o->fps);
  });
}

} // namespace talus::cli
