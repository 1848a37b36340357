#pragma once
// Pictures and movies of a run folder's snapshots: what `talus render`, `talus movie` and the
// pictures a scenario asks for at the end of `talus run` share.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/frame.hpp"
#include "scenario/file/picture_request.hpp"

namespace talus::cli {

struct Snapshot {
  double time;
  std::filesystem::path particles, walls, contacts;
};

/// The snapshots listed in DIR/particles.pvd; throws InvalidArgument when there are none.
std::vector<Snapshot> snapshots_of(const std::filesystem::path& dir);

/// Reads one snapshot, contacts included.
Frame load_snapshot(const Snapshot& s);

/// "all", "last" or a snapshot number; throws InvalidArgument naming the allowed values.
std::vector<std::size_t> pick_frames(const std::string& which, std::size_t n);

/// Draws the picked snapshots of a run into `out` as STEM_NNNNNN.png; returns how many.
/// With r.tracks, the run's track.csv must exist (InvalidArgument otherwise).
std::size_t render_run(const std::filesystem::path& dir, const PictureRequest& r,
                       const std::string& frames, int width, const std::filesystem::path& out);

/// Writes DIR/movie.mp4 from every snapshot with ffmpeg, time stamped; returns the frame count.
std::size_t make_movie(const std::filesystem::path& dir, const PictureRequest& r, double fps,
                       int width);

} // namespace talus::cli
