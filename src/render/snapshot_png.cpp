#include "render/snapshot_png.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <cairo.h>
#include <fmt/core.h>

namespace talus {

namespace {

struct Rgb {
  double r, g, b;
};

// A perceptually ordered dark-blue -> teal -> yellow ramp (viridis-like), u in [0, 1].
Rgb ramp(double u) {
  static constexpr Rgb stops[5] = {{0.267, 0.005, 0.329},
                                   {0.229, 0.322, 0.545},
                                   {0.128, 0.567, 0.551},
                                   {0.369, 0.789, 0.383},
                                   {0.993, 0.906, 0.144}};
  u = std::clamp(u, 0.0, 1.0) * 4.0;
  const int k = std::min(3, static_cast<int>(u));
  const double f = u - k;
  return {stops[k].r + f * (stops[k + 1].r - stops[k].r),
          stops[k].g + f * (stops[k + 1].g - stops[k].g),
          stops[k].b + f * (stops[k + 1].b - stops[k].b)};
}

} // namespace

void write_snapshot_png(const Simulation& sim, const std::string& path, int width_px,
                        SnapshotColour colour) {
  const Particles& p = sim.world().particles;
  Vec2 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec2 hi{std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  for (std::size_t i = 0; i < p.size(); ++i) {
    lo = {std::min(lo.x, p.position[i].x - p.radius[i]),
          std::min(lo.y, p.position[i].y - p.radius[i])};
    hi = {std::max(hi.x, p.position[i].x + p.radius[i]),
          std::max(hi.y, p.position[i].y + p.radius[i])};
  }
  for (const Segment& s : sim.world().walls)
    for (const Vec2 e : {s.a, s.b})
      lo = {std::min(lo.x, e.x), std::min(lo.y, e.y)},
      hi = {std::max(hi.x, e.x), std::max(hi.y, e.y)};
  if (!(hi.x > lo.x && hi.y > lo.y)) throw std::runtime_error("nothing to draw in " + path);

  const double margin = 0.03 * (hi.x - lo.x);
  const double bar_px = 70.0;
  const double scale = (width_px - bar_px) / (hi.x - lo.x + 2.0 * margin);
  const int height_px = static_cast<int>(std::ceil((hi.y - lo.y + 2.0 * margin) * scale)) + 40;
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width_px, height_px);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_paint(cr);
  const auto X = [&](double x) { return (x - lo.x + margin) * scale; };
  const auto Y = [&](double y) { return height_px - 20.0 - (y - lo.y + margin) * scale; };

  std::vector<double> value(p.size());
  double vmin = std::numeric_limits<double>::max(), vmax = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    value[i] = colour == SnapshotColour::speed ? norm(p.velocity[i]) : p.radius[i];
    if (p.is_free(i)) vmin = std::min(vmin, value[i]), vmax = std::max(vmax, value[i]);
  }
  if (vmin > vmax) vmin = vmax = 0.0;
  const double span = vmax > vmin ? vmax - vmin : 1.0;

  for (std::size_t i = 0; i < p.size(); ++i) {
    cairo_arc(cr, X(p.position[i].x), Y(p.position[i].y), p.radius[i] * scale, 0.0,
              2.0 * std::numbers::pi);
    if (p.is_free(i)) {
      const Rgb c = ramp((value[i] - vmin) / span);
      cairo_set_source_rgb(cr, c.r, c.g, c.b);
    } else {
      cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
    }
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_set_line_width(cr, 3.0);
  for (const Segment& s : sim.world().walls) {
    cairo_move_to(cr, X(s.a.x), Y(s.a.y));
    cairo_line_to(cr, X(s.b.x), Y(s.b.y));
    cairo_stroke(cr);
  }

  // colour bar with its range and unit
  const double bx = width_px - bar_px + 15.0, by = 30.0, bh = height_px - 80.0;
  for (int k = 0; k < 100; ++k) {
    const Rgb c = ramp(1.0 - k / 99.0);
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_rectangle(cr, bx, by + bh * k / 100.0, 18.0, bh / 100.0 + 1.0);
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 12.0);
  const bool speed = colour == SnapshotColour::speed;
  const double unit = speed ? 1.0 : 1e3;
  const std::string top = fmt::format("{:.3g}", vmax * unit),
                    bottom = fmt::format("{:.3g}", vmin * unit);
  cairo_move_to(cr, bx - 5.0, by - 8.0);
  cairo_show_text(cr, top.c_str());
  cairo_move_to(cr, bx - 5.0, by + bh + 16.0);
  cairo_show_text(cr, bottom.c_str());
  cairo_move_to(cr, bx - 10.0, by + bh + 32.0);
  cairo_show_text(cr, speed ? "|v| m/s" : "R mm");
  const std::string stamp = fmt::format("t = {:.4f} s   N = {}", sim.time(), p.size());
  cairo_move_to(cr, 10.0, 16.0);
  cairo_show_text(cr, stamp.c_str());

  cairo_destroy(cr);
  const cairo_status_t status = cairo_surface_write_to_png(surface, path.c_str());
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error("cannot write picture " + path + ": " +
                             cairo_status_to_string(status));
}

} // namespace talus
