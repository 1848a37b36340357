// The snapshot picture is looked at, not only written: size, and a grain drawn where it is.
#include <gtest/gtest.h>

#include <array>
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

TEST(SnapshotPng, DrawsATrackWhereTheParticleWent) {
  // a grain at the right end of a horizontal path across empty space; the path is drawn red
  Frame f;
  f.id = {0, 1};
  f.position = {{0.09, 0.05}, {0.01, 0.09}};
  f.radius = {0.005, 0.005};
  f.velocity = {{}, {}};
  f.force = {{}, {}};
  f.kind = {0, 0};
  f.material = {0, 0};
  f.walls = {{{0.0, 0.0}, {0.1, 0.0}}};
  PictureOptions o;
  o.width_px = 600;
  o.bounds = Rect{{0.0, 0.0}, {0.1, 0.1}};
  o.tracks = {{0, {{0.01, 0.05}, {0.05, 0.05}, {0.09, 0.05}}}};
  const auto path = (std::filesystem::temp_directory_path() / "talus_track_test.png").string();
  write_frame_png(f, path, o);
  cairo_surface_t* img = cairo_image_surface_create_from_png(path.c_str());
  ASSERT_EQ(cairo_surface_status(img), CAIRO_STATUS_SUCCESS);
  const int height = cairo_image_surface_get_height(img);
  const auto* data = cairo_image_surface_get_data(img);
  const int stride = cairo_image_surface_get_stride(img);
  const auto pixel = [&](double x, double y) {
    const double scale = (600.0 - 70.0) / (0.1 + 2.0 * 0.003);
    const int px = static_cast<int>((x + 0.003) * scale);
    const int py = static_cast<int>(height - 20.0 - (y + 0.003) * scale);
    return *reinterpret_cast<const std::uint32_t*>(data + py * stride + 4 * px) & 0xFFFFFFu;
  };
  const std::uint32_t on_path = pixel(0.03, 0.05);
  const unsigned red = (on_path >> 16) & 0xFFu, green = (on_path >> 8) & 0xFFu;
  EXPECT_GT(red, 180u) << "the track is not drawn red where the particle went";
  EXPECT_LT(green, 80u);
  EXPECT_EQ(pixel(0.03, 0.02), 0xFFFFFFu) << "off the path stays white";
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

namespace talus {
namespace {

TEST(SnapshotPng, ForceChainIsDrawnDarkerThanTheFadedGrains) {
  Frame f;
  f.position = {{0.0, 0.0}, {0.02, 0.0}};
  f.radius = {0.011, 0.011};
  f.velocity = {{0.0, 0.0}, {0.0, 0.0}};
  f.force = f.velocity;
  f.kind = {0, 0};
  f.material = {0, 0};
  f.chains.push_back({{0.0, 0.0}, {0.02, 0.0}, 5.0});
  const auto path = (std::filesystem::temp_directory_path() / "talus_chain_test.png").string();
  PictureOptions o;
  o.width_px = 600;
  o.chains = true;
  write_frame_png(f, path, o);
  cairo_surface_t* img = cairo_image_surface_create_from_png(path.c_str());
  ASSERT_EQ(cairo_surface_status(img), CAIRO_STATUS_SUCCESS);
  const int height = cairo_image_surface_get_height(img),
            stride = cairo_image_surface_get_stride(img);
  const auto* data = cairo_image_surface_get_data(img);
  const auto rgb = [&](int x, int y) {
    const std::uint32_t v = *reinterpret_cast<const std::uint32_t*>(data + y * stride + 4 * x);
    return std::array<int, 3>{int((v >> 16) & 255), int((v >> 8) & 255), int(v & 255)};
  };
  // the chain runs along y = 0 between the centres: the middle of the picture's drawing
  const Rect b = frame_bounds(f);
  const double margin = 0.03 * (b.hi.x - b.lo.x),
               scale = (600.0 - 70.0) / (b.hi.x - b.lo.x + 2 * margin);
  const int cx = static_cast<int>((0.01 - b.lo.x + margin) * scale);
  const int cy = static_cast<int>(height - 20.0 - (0.0 - b.lo.y + margin) * scale);
  const auto chain = rgb(cx, cy);
  EXPECT_GT(chain[0], 2 * chain[1]) << "the chain pixel is not red"; // red dominates
  // inside the first grain, clear of the chain: (0, 0.006) m
  const auto grain =
      rgb(static_cast<int>((0.0 - b.lo.x + margin) * scale), static_cast<int>(cy - 0.006 * scale));
  EXPECT_LT(grain[0] + grain[1] + grain[2], 3 * 255) << "the grain is not drawn there";
  EXPECT_GT(grain[1], chain[1] + 60) << "the faded grain is not lighter than the chain";
  // the colour bar fades as the grains do: the bottom of the bar (the lowest speed, which both
  // grains at rest have) is the grains' colour, to a few levels of rounding
  const auto bar = rgb(600 - 70 + 15 + 9, height - 52);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(bar[k], grain[k], 3) << "channel " << k;
  // a length scale in the top strip: a black bar from x = 10 px at y = 34 px
  const auto scale_bar = rgb(30, 34);
  EXPECT_LT(scale_bar[0] + scale_bar[1] + scale_bar[2], 3 * 60) << "no length scale";
  cairo_surface_destroy(img);
  std::filesystem::remove(path);
}

} // namespace
} // namespace talus
