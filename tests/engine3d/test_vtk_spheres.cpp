// A 3D scene's ParaView files (io/vtk_spheres.hpp) open in VTK's own reader with the spheres
// where they are, the box in their field data, the contacts as lines and the arrays the docs name
// (read_vtk_spheres.py; skipped without VTK).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <unistd.h>

#include "analysis/contact_forces3.hpp"
#include "engine3d/simulation3.hpp"
#include "io/vtk_spheres.hpp"
#include "support/two_body.hpp"

namespace talus {
namespace {

void write(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

TEST(VtkSpheres, ParaViewsReaderOpensTheSpheresAndPlates) {
  Scene3 scene;
  scene.materials = {testing::elastic_material()};
  scene.gravity = {0.0, 0.0, -9.81};
  scene.plates = box_planes({0.0, 0.0, 0.0}, {0.02, 0.02, 0.02}, 0, true);
  scene.plates.push_back(make_plane({0.01, 0.01, 0.015}, {0.0, 1.0, 1.0}, 0.004, 0.002));
  for (int k = 0; k < 5; ++k)
    scene.add_sphere({.position = {0.003 + 0.0035 * k, 0.01, 0.0015 + 0.001 * k},
                      .radius = 0.0015,
                      .angular_velocity = {1.0 * k, -2.0, 0.5}});
  Simulation3 s(std::move(scene), {.timestep = 1e-6});
  s.run(200);
  const auto dir =
      std::filesystem::temp_directory_path() / ("talus_vtk_spheres_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  write(dir / "spheres.vtp", vtp_spheres(s.scene()));
  write(dir / "plates.vtp", vtp_plates(s.scene(), 0.02));
  write(dir / "contacts.vtp", vtp_contacts3(s));
  std::string positions;
  for (const Vec3& p : s.scene().spheres.position)
    positions +=
        fmt::format("{}[{:.17g}, {:.17g}, {:.17g}]", positions.empty() ? "" : ", ", p.x, p.y, p.z);
  const Vec3 w = s.scene().spheres.angular_velocity[0];
  const Domain3& box = s.scene().domain;
  write(dir / "expected.json",
        fmt::format(R"({{"positions": [{}], "spin0": [{:.17g}, {:.17g}, {:.17g}], "plates": {}, )"
                    R"("contacts": {}, "box": [{}, {}, {}, {}, {}, {}]}})",
                    positions, w.x, w.y, w.z, s.scene().plates.size(), contact_records3(s).size(),
                    box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z));
  const std::string script = std::string(TALUS_SOURCE_DIR) + "/tests/engine3d/read_vtk_spheres.py";
  const int status = std::system(("/usr/bin/python3 " + script + " " + dir.string()).c_str());
  std::filesystem::remove_all(dir);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 77) GTEST_SKIP() << "python3-vtk9 missing";
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "read_vtk_spheres.py failed";
}

} // namespace
} // namespace talus
