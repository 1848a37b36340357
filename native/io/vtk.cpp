#include "io/vtk.hpp"

#include <fmt/format.h>

#include "analysis/observables.hpp"
#include "analysis/stress.hpp"
#include "io/vtk_arrays.hpp"

namespace talus {

using vtk_detail::array;

std::string vtp_particles(const Simulation& sim, bool stress) {
  const Particles& p = sim.world().particles;
  const std::size_t n = p.size();
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
                    "byte_order=\"LittleEndian\">\n  <PolyData>\n";
  out += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\">\n", n, n);
  out += "      <PointData Scalars=\"radius\">\n";
  array(out, "id", 1, n, [&](std::size_t i) { return fmt::format("{}", p.id[i]); });
  array(out, "radius", 1, n, [&](std::size_t i) { return fmt::format("{:.9g}", p.radius[i]); });
  array(out, "velocity", 3, n, [&](std::size_t i) {
    return fmt::format("{:.9g} {:.9g} 0", p.velocity[i].x, p.velocity[i].y);
  });
  array(out, "angular_velocity", 1, n,
        [&](std::size_t i) { return fmt::format("{:.9g}", p.angular_velocity[i]); });
  array(out, "force", 3, n,
        [&](std::size_t i) { return fmt::format("{:.9g} {:.9g} 0", p.force[i].x, p.force[i].y); });
  array(out, "kind", 1, n,
        [&](std::size_t i) { return fmt::format("{}", static_cast<int>(p.kind[i])); });
  array(out, "material", 1, n, [&](std::size_t i) { return fmt::format("{}", p.material[i]); });
  array(out, "mass", 1, n, [&](std::size_t i) { return fmt::format("{:.9g}", p.mass[i]); });
  if (stress) {
    const std::vector<Tensor2> s = particle_stresses(sim);
    array(out, "stress", 9, n, [&](std::size_t i) {
      return fmt::format("{:.9g} {:.9g} 0 {:.9g} {:.9g} 0 0 0 0", s[i](0, 0), s[i](0, 1),
                         s[i](1, 0), s[i](1, 1));
    });
  }
  out += "      </PointData>\n      <Points>\n";
  array(out, "position", 3, n, [&](std::size_t i) {
    return fmt::format("{:.12g} {:.12g} 0", p.position[i].x, p.position[i].y);
  });
  out += "      </Points>\n";
  vtk_detail::end_with_verts(out, n);
  return out;
}

namespace {

// A line's end as VTK's three coordinates, z = 0.
template <class End> auto end_text(End end) {
  return [end](std::size_t k, bool second) {
    const Vec2 v = end(k, second);
    return fmt::format("{:.12g} {:.12g} 0", v.x, v.y);
  };
}

} // namespace

std::string vtp_walls(const Simulation& sim) {
  const Segments& w = sim.world().walls;
  return vtk_detail::line_polydata(
      w.size(), "",
      [&](std::string& out) {
        array(out, "force", 3, w.size(), [&](std::size_t s) {
          return fmt::format("{:.9g} {:.9g} 0", w[s].force.x, w[s].force.y);
        });
      },
      end_text([&](std::size_t s, bool second) { return second ? w[s].b : w[s].a; }));
}

std::string vtp_contacts(const Simulation& sim) {
  const std::vector<ContactRecord> c = contact_forces(sim);
  const Particles& p = sim.world().particles;
  return vtk_detail::line_polydata(
      c.size(), "normal_force",
      [&](std::string& out) {
        vtk_detail::contact_scalars(out, c);
        array(out, "contact_point", 3, c.size(), [&](std::size_t k) {
          return fmt::format("{:.9g} {:.9g} 0", c[k].point.x, c[k].point.y);
        });
        // the force on `particle` (on `partner`: its opposite), for stresses and fields
        array(out, "force", 3, c.size(), [&](std::size_t k) {
          return fmt::format("{:.9g} {:.9g} 0", c[k].force.x, c[k].force.y);
        });
        // ids, as the particles' "id" array: indices change when the engine renumbers
        array(out, "particle", 1, c.size(),
              [&](std::size_t k) { return fmt::format("{}", p.id[c[k].i]); });
        array(out, "partner", 1, c.size(), [&](std::size_t k) {
          return fmt::format(
              "{}", c[k].j >= 0 ? std::int64_t{p.id[static_cast<std::size_t>(c[k].j)]} : c[k].j);
        });
      },
      end_text([&](std::size_t k, bool second) { return second ? c[k].to : c[k].from; }));
}

std::string pvd_collection(const std::vector<std::pair<double, std::string>>& entries) {
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\">\n"
                    "  <Collection>\n";
  for (const auto& [t, file] : entries)
    out += fmt::format("    <DataSet timestep=\"{:.9g}\" part=\"0\" file=\"{}\"/>\n", t, file);
  out += "  </Collection>\n</VTKFile>\n";
  return out;
}

} // namespace talus
