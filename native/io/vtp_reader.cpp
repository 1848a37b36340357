#include "io/vtp_reader.hpp"

#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>

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

namespace {

bool has_array(const std::string& xml, const std::string& name) {
  return xml.find("Name=\"" + name + "\"") != std::string::npos;
}

// The vector of the three numbers at v: 2D's frames keep x and y.
template <class V> V vector_at(const double* v) {
  if constexpr (std::is_same_v<V, Vec2>)
    return {v[0], v[1]};
  else
    return {v[0], v[1], v[2]};
}

// The contacts of a contacts .vtp file into f's chains; the force vectors, contact points and
// partners' kinds where the file has them (snapshots from before they were written lack them).
template <class FrameT> void read_chains(const std::string& contacts, FrameT& f) {
  using V = typename decltype(f.position)::value_type;
  const std::string c = read_file(contacts);
  const auto points = data_array(c, "position", contacts);
  const auto normal = data_array(c, "normal_force", contacts);
  const std::size_t n = normal.size();
  if (points.size() != 6 * n) throw std::runtime_error(contacts + ": arrays of different lengths");
  const bool vectors = has_array(c, "force") && has_array(c, "particle");
  std::vector<double> force, point, particle, partner;
  if (vectors) {
    force = data_array(c, "force", contacts), point = data_array(c, "contact_point", contacts);
    particle = data_array(c, "particle", contacts), partner = data_array(c, "partner", contacts);
    if (force.size() != 3 * n || point.size() != 3 * n || particle.size() != n ||
        partner.size() != n)
      throw std::runtime_error(contacts + ": arrays of different lengths");
  }
  std::unordered_map<std::int64_t, bool> free_by_id;
  for (std::size_t i = 0; i < f.id.size(); ++i) free_by_id[f.id[i]] = f.kind[i] == 0;
  const auto is_free = [&](double id) {
    const auto at = free_by_id.find(static_cast<std::int64_t>(id));
    return at != free_by_id.end() && at->second;
  };
  for (std::size_t k = 0; k < n; ++k) {
    typename FrameT::Chain ch{vector_at<V>(&points[6 * k]), vector_at<V>(&points[6 * k + 3]),
                              normal[k]};
    ch.has_vector = vectors;
    if (vectors) {
      ch.force_on_from = vector_at<V>(&force[3 * k]);
      ch.point = vector_at<V>(&point[3 * k]);
      ch.from_free = is_free(particle[k]);
      ch.to_free = partner[k] >= 0 && is_free(partner[k]);
    }
    f.chains.push_back(ch);
  }
}

} // namespace

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
  if (has_array(xml, "mass")) {
    f.mass = data_array(xml, "mass", particles);
    if (f.mass.size() != n) throw std::runtime_error(particles + ": arrays of different lengths");
  }
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
  if (!contacts.empty() && std::filesystem::exists(contacts)) read_chains(contacts, f);
  return f;
}

Frame3 read_vtp_frame3(const std::string& spheres, double time, const std::string& contacts) {
  const std::string xml = read_file(spheres);
  Frame3 f;
  f.time = time;
  const auto pos = data_array(xml, "position", spheres);
  f.radius = data_array(xml, "radius", spheres);
  const auto vel = data_array(xml, "velocity", spheres);
  const auto kind = data_array(xml, "kind", spheres);
  const auto ids = data_array(xml, "id", spheres);
  f.mass = data_array(xml, "mass", spheres);
  const std::size_t n = f.radius.size();
  if (pos.size() != 3 * n || vel.size() != 3 * n || kind.size() != n || ids.size() != n ||
      f.mass.size() != n)
    throw std::runtime_error(spheres + ": arrays of different lengths");
  for (std::size_t i = 0; i < n; ++i) {
    f.id.push_back(entry_of<std::uint32_t>(ids, i, "id", spheres));
    f.position.push_back(vector_at<Vec3>(&pos[3 * i]));
    f.velocity.push_back(vector_at<Vec3>(&vel[3 * i]));
    f.kind.push_back(entry_of<std::uint8_t>(kind, i, "kind", spheres));
  }
  if (has_array(xml, "box")) { // snapshots from before the box was written lack it
    const auto box = data_array(xml, "box", spheres);
    const auto periodic = data_array(xml, "periodic", spheres);
    const auto slide = data_array(xml, "shear_velocity", spheres);
    if (box.size() != 6 || periodic.size() != 3 || slide.size() != 1)
      throw std::runtime_error(spheres + ": a box of the wrong size in its field data");
    f.box_lo = vector_at<Vec3>(&box[0]), f.box_hi = vector_at<Vec3>(&box[3]);
    for (int a = 0; a < 3; ++a) f.periodic[static_cast<std::size_t>(a)] = periodic[a] != 0.0;
    f.shear_velocity = slide[0];
  }
  if (!contacts.empty() && std::filesystem::exists(contacts)) read_chains(contacts, f);
  return f;
}

} // namespace talus
