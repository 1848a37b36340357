#pragma once
// A picture a scenario asks for at the end of a run: "COLOUR[+chains][+tracks]".
#include <string>
#include <string_view>

namespace talus {

struct PictureRequest {
  std::string colour = "speed"; ///< speed | size | force | kind | material
  bool chains = false;          ///< force chains over the grains
  bool tracks = false;          ///< trajectories of the tracked particles
};

/// What is wrong with a request, with the allowed values; empty when it is fine.
std::string picture_request_problem(std::string_view text);

/// Parses "speed", "force+chains", "size+tracks", ...; throws InvalidArgument on bad text.
PictureRequest parse_picture_request(std::string_view text);

/// The file stem of a request's pictures, e.g. "force_chains".
std::string picture_stem(const PictureRequest& r);

} // namespace talus
