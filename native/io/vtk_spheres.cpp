#include "io/vtk_spheres.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "analysis/contact_forces3.hpp"
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

// The box as the run had it then (a cell strains it), for what is computed from the snapshots:
// its corners, which axes are periodic, and the x velocity of the image above (Lees-Edwards).
void box_field_data(std::string& out, const Domain3& d) {
  const auto one = [&out](const char* name, int components, const std::string& values) {
    out += fmt::format("      <DataArray type=\"Float64\" Name=\"{}\" NumberOfTuples=\"1\" "
                       "NumberOfComponents=\"{}\" format=\"ascii\">\n        {}\n"
                       "      </DataArray>\n",
                       name, components, values);
  };
  out += "    <FieldData>\n";
  one("box", 6, triple(d.lo) + " " + triple(d.hi));
  one("periodic", 3,
      fmt::format("{} {} {}", int{d.periodic[0]}, int{d.periodic[1]}, int{d.periodic[2]}));
  one("shear_velocity", 1, fmt::format("{}", d.shear_velocity));
  out += "    </FieldData>\n";
}

} // namespace

std::string vtp_spheres(const Scene3& scene, std::span<const Tensor3> stress) {
  const Spheres& s = scene.spheres;
  const std::size_t n = s.size();
  std::string out = header;
  box_field_data(out, scene.domain);
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

std::string vtp_contacts3(const Simulation3& sim) {
  const std::vector<ContactRecord3> c = contact_records3(sim);
  const Spheres& s = sim.scene().spheres;
  const auto g9 = [](const Vec3& v) { return fmt::format("{:.9g} {:.9g} {:.9g}", v.x, v.y, v.z); };
  return vtk_detail::line_polydata(
      c.size(), "normal_force",
      [&](std::string& out) {
        vtk_detail::contact_scalars(out, c);
        array(out, "contact_point", 3, c.size(), [&](std::size_t k) { return g9(c[k].point); });
        array(out, "force", 3, c.size(), [&](std::size_t k) { return g9(c[k].force); });
        // ids, as the spheres' "id" array: indices change when the engine renumbers
        array(out, "particle", 1, c.size(),
              [&](std::size_t k) { return fmt::format("{}", s.id[c[k].i]); });
        array(out, "partner", 1, c.size(), [&](std::size_t k) {
          const std::int64_t j = c[k].j;
          return fmt::format("{}", j >= 0 ? std::int64_t{s.id[static_cast<std::size_t>(j)]} : j);
        });
      },
      [&](std::size_t k, bool second) { return triple(second ? c[k].to : c[k].from); });
}

} // namespace talus
