#include "io/track_csv.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/whole_number.hpp"

namespace talus {

std::map<std::uint32_t, std::vector<TrackPoint>> read_tracks(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string line;
  std::getline(in, line);
  if (line.rfind("time,id,x,y", 0) != 0)
    throw std::runtime_error(path + ": not a talus track file (header '" + line + "')");
  const int columns = line.find(",xu,yu") != std::string::npos ? 10 : 8;
  std::map<std::uint32_t, std::vector<TrackPoint>> tracks;
  for (std::size_t number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    std::istringstream row(line);
    double v[10];
    char comma = ',';
    bool ok = static_cast<bool>(row >> v[0]);
    for (int k = 1; k < columns && ok; ++k)
      ok = static_cast<bool>(row >> comma >> v[k]) && comma == ',';
    if (!ok) throw std::runtime_error(path + ":" + std::to_string(number) + ": malformed row");
    const auto id =
        whole_number<std::uint32_t>(v[1], path + ":" + std::to_string(number) + ": the id");
    const Vec2 position{v[2], v[3]};
    tracks[id].push_back(
        {v[0], position, {v[5], v[6]}, columns == 10 ? Vec2{v[8], v[9]} : position});
  }
  return tracks;
}

} // namespace talus
