#include "scenario/file/picture_request.hpp"

#include <array>

#include "talus/error.hpp"

namespace talus {

namespace {

constexpr std::array<std::string_view, 5> colours = {"speed", "size", "force", "kind", "material"};

std::string parse(std::string_view text, PictureRequest& r) {
  const auto plus = text.find('+');
  const std::string_view colour = text.substr(0, plus);
  bool known = false;
  for (const auto c : colours) known = known || c == colour;
  if (!known)
    return "colour '" + std::string(colour) + "' is not one of: speed, size, force, kind, material";
  r.colour = colour;
  while (plus != std::string_view::npos && !text.empty()) {
    text = text.substr(text.find('+') + 1);
    const auto next = text.find('+');
    const std::string_view layer = text.substr(0, next);
    if (layer == "chains")
      r.chains = true;
    else if (layer == "tracks")
      r.tracks = true;
    else
      return "layer '" + std::string(layer) + "' is not one of: chains, tracks";
    if (next == std::string_view::npos) break;
  }
  return {};
}

} // namespace

std::string picture_request_problem(std::string_view text) {
  PictureRequest r;
  const std::string problem = parse(text, r);
  return problem.empty() ? problem
                         : problem + " (a picture is COLOUR[+chains][+tracks], e.g. force+chains)";
}

PictureRequest parse_picture_request(std::string_view text) {
  PictureRequest r;
  if (const std::string problem = parse(text, r); !problem.empty())
    throw InvalidArgument("picture '" + std::string(text) + "': " + problem);
  return r;
}

std::string picture_stem(const PictureRequest& r) {
  return r.colour + (r.chains ? "_chains" : "") + (r.tracks ? "_tracks" : "");
}

} // namespace talus
