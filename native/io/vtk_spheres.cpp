#include "io/vtk_spheres.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "io/vtk_arrays.hpp"

namespace talus {

using vtk_detail::array;

namespace {

// Every number as the shortest text that reads back to the same double: a snapshot holds the
// exact state, which validation/crosscheck3d.py compares with LAMMPS' to rounding.
std::string triple(const Vec3& v) {
  return fmt::format("{} {} {}", v.x, v.y, v.z);
}

const char* const header = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
                           "byte_order=\"LittleEndian\">\n  <PolyData>\n";

} // namespace

std::string vtp_spheres(const Scene3& scene, std::span<const Tensor3> stress) {
  const Spheres& s = scene.spheres;
  const std::size_t n = s.size();
  std::string out = header;
  out += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\">\n", n, n);
  out += "      <PointData Scalars=\"radius\">\n";
  array(out, "id", 1, n, [&](std::size_t i) { return fmt::format("{}", s.id[i]); });
  array(out, "radius", 1, n, [&](std::size_t i) { return fmt::format("{}", s.radius[i]); });
  array(out, "velocity", 3, n, [&](std::size_t i) { return triple(s.velocity[i]); });
  array(out, "angular_velocity", 3, n,
        [&](std::size_t i) { return triple(s.angular_velocity[i]); });
  array(out, "force", 3, n, [&](std::size_t i) { return triple(s.force[i]); });
  array(out, "kind", 1, n,
        [&](std::size_t i) { return fmt::format("{}", static_cast<int>(s.kind[i])); });
  array(out, "material", 1, n, [&](std::size_t i) { return fmt::format("{}", s.material[i]); });
  array(out, "mass", 1, n, [&](std::size_t i) { return fmt::format("{}", s.mass[i]); });
  if (!stress.empty())
    array(out, "stress", 9, n, [&](std::size_t i) {
      const Tensor3& t = stress[i];
      return fmt::format("{:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g}", t(0, 0),
                         t(0, 1), t(0, 2), t(1, 0), t(1, 1), t(1, 2), t(2, 0), t(2, 1), t(2, 2));
    });
  out += "      </PointData>\n      <Points>\n";
  array(out, "position", 3, n, [&](std::size_t i) { return triple(s.position[i]); });
  out += "      </Points>\n";
  vtk_detail::end_with_verts(out, n);
  return out;
}

std::string vtp_plates(const Scene3& scene, double reach) {
  const auto& plates = scene.plates;
  const std::size_t n = plates.size();
  std::string out = header;
  out += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfPolys=\"{}\">\n", 4 * n, n);
  out += "      <CellData>\n";
  array(out, "force", 3, n, [&](std::size_t k) { return triple(plates[k].force); });
  array(out, "material", 1, n,
        [&](std::size_t k) { return fmt::format("{}", plates[k].material); });
  out += "      </CellData>\n      <Points>\n";
  array(out, "corners", 3, 4 * n, [&](std::size_t c) {
    const Plane& p = plates[c / 4];
    const double su = (c % 4 == 0 || c % 4 == 3) ? -1.0 : 1.0, sv = c % 4 < 2 ? -1.0 : 1.0;
    const Vec3 corner = p.centre + (su * std::min(p.half_u, reach)) * p.axis_u +
                        (sv * std::min(p.half_v, reach)) * p.axis_v();
    return triple(corner);
  });
  out += "      </Points>\n      <Polys>\n"
         "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < n; ++k)
    out += fmt::format("{} {} {} {}\n", 4 * k, 4 * k + 1, 4 * k + 2, 4 * k + 3);
  out += "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" "
         "format=\"ascii\">\n";
  for (std::size_t k = 0; k < n; ++k) out += fmt::format("{}\n", 4 * (k + 1));
  out += "        </DataArray>\n      </Polys>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  return out;
}

} // namespace talus
