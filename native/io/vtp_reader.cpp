#include "io/vtp_reader.hpp"

#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "io/checkpoint.hpp"
#include "io/whole_number.hpp"

namespace talus {

namespace {

std::string attribute(const std::string& tag, const std::string& name) {
  const auto at = tag.find(name + "=\"");
  if (at == std::string::npos) return {};
  const auto start = at + name.size() + 2;
  return tag.substr(start, tag.find('"', start) - start);
}

// The numbers of the DataArray named `name` (all components, in order).
std::vector<double> data_array(const std::string& xml, const std::string& name,
                               const std::string& file) {
  std::size_t at = 0;
  while ((at = xml.find("<DataArray", at)) != std::string::npos) {
    const auto end_tag = xml.find('>', at);
    const std::string tag = xml.substr(at, end_tag - at);
    if (attribute(tag, "Name") == name) {
      const auto close = xml.find("</DataArray>", end_tag);
      if (close == std::string::npos) break;
      std::istringstream in(xml.substr(end_tag + 1, close - end_tag - 1));
      std::vector<double> values;
      for (double v; in >> v;) values.push_back(v);
      return values;
    }
    at = end_tag;
  }
  throw std::runtime_error(file + ": no DataArray '" + name + "' (not a talus snapshot?)");
}

// Entry k of a DataArray of whole numbers (ids, kinds, materials) as T.
template <class T>
T entry_of(const std::vector<double>& values, std::size_t k, const char* name,
           const std::string& file) {
  return whole_number<T>(values[k],
                         file + ": DataArray '" + name + "' at entry " + std::to_string(k));
}

} // namespace

std::vector<std::pair<double, std::string>> read_pvd(const std::string& path) {
  const std::string xml = read_file(path);
  std::vector<std::pair<double, std::string>> out;
  std::size_t at = 0;
  while ((at = xml.find("<DataSet", at)) != std::string::npos) {
    const auto end = xml.find('>', at);
    const std::string tag = xml.substr(at, end - at);
    try {
      out.emplace_back(std::stod(attribute(tag, "timestep")), attribute(tag, "file"));
    } catch (const std::exception&) {
      throw std::runtime_error(path + ": a DataSet without a timestep");
    }
    at = end;
  }
  return out;
}

std::vector<double> read_contact_normal_forces(const std::string& contacts) {
  return data_array(read_file(contacts), "normal_force", contacts);
}

Frame read_vtp_frame(const std::string& particles, const std::string& walls, double time,
                     const std::string& contacts) {
  const std::string xml = read_file(particles);
  Frame f;
  f.time = time;
  const auto pos = data_array(xml, "position", particles);
  const auto radius = data_array(xml, "radius", particles);
  const auto vel = data_array(xml, "velocity", particles);
  const auto force = data_array(xml, "force", particles);
  const auto kind = data_array(xml, "kind", particles);
  const auto material = data_array(xml, "material", particles);
  const auto ids = data_array(xml, "id", particles);
  const std::size_t n = radius.size();
  if (pos.size() != 3 * n || vel.size() != 3 * n || force.size() != 3 * n || kind.size() != n ||
      material.size() != n || ids.size() != n)
    throw std::runtime_error(particles + ": arrays of different lengths");
  for (std::size_t i = 0; i < n; ++i) {
    f.id.push_back(entry_of<std::uint32_t>(ids, i, "id", particles));
    f.position.push_back({pos[3 * i], pos[3 * i + 1]});
    f.radius.push_back(radius[i]);
    f.velocity.push_back({vel[3 * i], vel[3 * i + 1]});
    f.force.push_back({force[3 * i], force[3 * i + 1]});
    f.kind.push_back(entry_of<std::uint8_t>(kind, i, "kind", particles));
    f.material.push_back(entry_of<std::uint16_t>(material, i, "material", particles));
  }
  if (!walls.empty() && std::filesystem::exists(walls)) {
    const auto w = data_array(read_file(walls), "position", walls);
    for (std::size_t k = 0; k + 6 <= w.size(); k += 6) // a, b as (x, y, 0) each
      f.walls.emplace_back(Vec2{w[k], w[k + 1]}, Vec2{w[k + 3], w[k + 4]});
  }
  if (!contacts.empty() && std::filesystem::exists(contacts)) {
    const std::string c = read_file(contacts);
    const auto points = data_array(c, "position", contacts);
    const auto normal = data_array(c, "normal_force", contacts);
    if (points.size() != 6 * normal.size())
      throw std::runtime_error(contacts + ": arrays of different lengths");
    for (std::size_t k = 0; k < normal.size(); ++k)
      f.chains.push_back(
          {{points[6 * k], points[6 * k + 1]}, {points[6 * k + 3], points[6 * k + 4]}, normal[k]});
  }
  return f;
}

} // namespace talus
