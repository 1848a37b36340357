// The snapshot picture is looked at, not only written: size, and a grain drawn where it is.
#include <gtest/gtest.h>

#include <cairo.h>
#include <cstdint>
#include <filesystem>

#include "render/snapshot_png.hpp"

namespace talus {
namespace {

TEST(SnapshotPng, DrawsTheGrainWhereItIsAndTheBackgroundWhite) {
  World w;
  Material m;
  m.normal_stiffness = 1e4;
  w.materials = {m};
  w.add_wall({0.0, 0.0}, {0.1, 0.0});
  w.add_particle({.position = {0.05, 0.02}, .radius = 0.01});
  SimulationConfig c;
  c.timestep = 1e-5;
  Simulation s(std::move(w), c);
  const auto path = (std::filesystem::temp_directory_path() / "talus_snapshot_test.png").string();
  write_snapshot_png(s, path, 600);

  cairo_surface_t* img = cairo_image_surface_create_from_png(path.c_str());
  ASSERT_EQ(cairo_surface_status(img), CAIRO_STATUS_SUCCESS);
  const int width = cairo_image_surface_get_width(img);
  const int height = cairo_image_surface_get_height(img);
  EXPECT_EQ(width, 600);
  EXPECT_GT(height, 100);
  const auto* data = cairo_image_surface_get_data(img);
  const int stride = cairo_image_surface_get_stride(img);
  const auto pixel = [&](int x, int y) {
    return *reinterpret_cast<const std::uint32_t*>(data + y * stride + 4 * x) & 0xFFFFFFu;
  };
  // same mapping as the renderer: x from the left edge of the drawing with a 3% margin
  const double scale = (600.0 - 70.0) / (0.1 + 2.0 * 0.003);
  const int gx = static_cast<int>((0.05 + 0.003) * scale);
  const int gy = static_cast<int>(height - 20.0 - (0.02 + 0.003) * scale);
  EXPECT_NE(pixel(gx, gy), 0xFFFFFFu) << "grain centre not drawn";
  EXPECT_EQ(pixel(5, height / 2), 0xFFFFFFu) << "background not white";
  cairo_surface_destroy(img);
  std::filesystem::remove(path);
}

TEST(SnapshotPng, UnwritablePathIsAClearError) {
  World w;
  Material m;
  m.normal_stiffness = 1e4;
  w.materials = {m};
  w.add_particle({.position = {0.0, 0.0}, .radius = 0.01});
  SimulationConfig c;
  c.timestep = 1e-5;
  Simulation s(std::move(w), c);
  EXPECT_THROW(write_snapshot_png(s, "/nonexistent-folder/x.png"), std::runtime_error);
}

} // namespace
} // namespace talus
