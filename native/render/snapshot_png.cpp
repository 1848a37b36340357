#include "render/snapshot_png.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <cairo.h>
#include <fmt/core.h>

#include "talus/error.hpp"

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

// Distinct colours for categories (kinds, materials).
Rgb category(std::size_t k) {
  static constexpr Rgb palette[8] = {
      {0.122, 0.467, 0.706}, {1.000, 0.498, 0.055}, {0.173, 0.627, 0.173}, {0.839, 0.153, 0.157},
      {0.580, 0.404, 0.741}, {0.549, 0.337, 0.294}, {0.890, 0.467, 0.761}, {0.498, 0.498, 0.498}};
  return palette[k % 8];
}

// Grains fade under force chains or tracks, so that those stand out; their colour key fades
// alike.
double grain_alpha(const PictureOptions& o) {
  return o.chains || !o.tracks.empty() ? 0.25 : 1.0;
}

bool continuous(SnapshotColour c) {
  return c == SnapshotColour::speed || c == SnapshotColour::size || c == SnapshotColour::force;
}

double field(const Frame& f, std::size_t i, SnapshotColour c) {
  switch (c) {
  case SnapshotColour::speed:
    return norm(f.velocity[i]);
  case SnapshotColour::size:
    return f.radius[i];
  case SnapshotColour::force:
    return norm(f.force[i]);
  case SnapshotColour::kind:
    return f.kind[i];
  case SnapshotColour::material:
    return f.material[i];
  }
  return 0.0;
}

} // namespace

SnapshotColour parse_colour(std::string_view name) {
  if (name == "speed") return SnapshotColour::speed;
  if (name == "size") return SnapshotColour::size;
  if (name == "force") return SnapshotColour::force;
  if (name == "kind") return SnapshotColour::kind;
  if (name == "material") return SnapshotColour::material;
  throw InvalidArgument("unknown colouring '" + std::string(name) +
                        "'; allowed: speed, size, force, kind, material");
}

Rect frame_bounds(const Frame& f) {
  Vec2 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec2 hi{std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  for (std::size_t i = 0; i < f.position.size(); ++i) {
    lo = {std::min(lo.x, f.position[i].x - f.radius[i]),
          std::min(lo.y, f.position[i].y - f.radius[i])};
    hi = {std::max(hi.x, f.position[i].x + f.radius[i]),
          std::max(hi.y, f.position[i].y + f.radius[i])};
  }
  for (const auto& [a, b] : f.walls)
    for (const Vec2 e : {a, b}) {
      lo = {std::min(lo.x, e.x), std::min(lo.y, e.y)};
      hi = {std::max(hi.x, e.x), std::max(hi.y, e.y)};
    }
  return {lo, hi};
}

namespace {

// Metres to pixels: the frame's box with a margin, y up, a strip on the right for the colour
// bar or legend.
struct Canvas {
  cairo_t* cr;
  Vec2 lo;
  double margin, scale;
  int height_px;
  static constexpr double bar_px = 70.0;
  double X(double x) const { return (x - lo.x + margin) * scale; }
  double Y(double y) const { return height_px - 20.0 - (y - lo.y + margin) * scale; }
};

// The colour scale's range: the free particles' values, or the one asked for.
std::pair<double, double> colour_range(const Frame& f, const PictureOptions& o) {
  double vmin = std::numeric_limits<double>::max(), vmax = 0.0;
  for (std::size_t i = 0; i < f.position.size(); ++i)
    if (f.kind[i] == 0)
      vmin = std::min(vmin, field(f, i, o.colour)), vmax = std::max(vmax, field(f, i, o.colour));
  if (vmin > vmax) vmin = vmax = 0.0;
  if (o.range) std::tie(vmin, vmax) = *o.range;
  return {vmin, vmax};
}

void draw_particles(const Canvas& cv, const Frame& f, const PictureOptions& o, double vmin,
                    double vmax) {
  const double span = vmax > vmin ? vmax - vmin : 1.0;
  for (std::size_t i = 0; i < f.position.size(); ++i) {
    cairo_arc(cv.cr, cv.X(f.position[i].x), cv.Y(f.position[i].y), f.radius[i] * cv.scale, 0.0,
              2.0 * std::numbers::pi);
    Rgb c{0.35, 0.35, 0.35}; // wall particles
    if (o.colour == SnapshotColour::kind)
      c = category(f.kind[i]);
    else if (o.colour == SnapshotColour::material)
      c = f.kind[i] == 0 ? category(f.material[i]) : c;
    else if (f.kind[i] == 0)
      c = ramp((field(f, i, o.colour) - vmin) / span);
    cairo_set_source_rgba(cv.cr, c.r, c.g, c.b, grain_alpha(o));
    cairo_fill(cv.cr);
  }
}

// Thesis figs. 1.1, 4.2, 4.13: width and darkness grow with the normal force, up to f_max.
void chain_pen(cairo_t* cr, double u) {
  cairo_set_source_rgb(cr, 0.8 * (1.0 - u) + 0.6 * u, 0.1 * (1.0 - u), 0.1 * (1.0 - u));
  cairo_set_line_width(cr, 0.5 + 5.5 * u);
}

double chain_force_scale(const Frame& f, const PictureOptions& o) {
  double f_max = 0.0;
  for (const auto& ch : f.chains) f_max = std::max(f_max, ch.force);
  return o.chain_scale ? *o.chain_scale : f_max;
}

void draw_chains(const Canvas& cv, const Frame& f, const PictureOptions& o) {
  const double f_max = chain_force_scale(f, o);
  cairo_set_line_cap(cv.cr, CAIRO_LINE_CAP_ROUND);
  for (const auto& ch : f.chains) {
    if (f_max <= 0.0 || ch.force <= 0.0) continue;
    chain_pen(cv.cr, std::min(1.0, ch.force / f_max));
    cairo_move_to(cv.cr, cv.X(ch.from.x), cv.Y(ch.from.y));
    cairo_line_to(cv.cr, cv.X(ch.to.x), cv.Y(ch.to.y));
    cairo_stroke(cv.cr);
  }
}

void draw_walls(const Canvas& cv, const Frame& f) {
  cairo_set_source_rgb(cv.cr, 0.0, 0.0, 0.0);
  cairo_set_line_width(cv.cr, 3.0);
  for (const auto& [a, b] : f.walls) {
    cairo_move_to(cv.cr, cv.X(a.x), cv.Y(a.y));
    cairo_line_to(cv.cr, cv.X(b.x), cv.Y(b.y));
    cairo_stroke(cv.cr);
  }
}

// Trajectories: a line each in a strong colour, a dot where the particle is now.
void draw_tracks(const Canvas& cv, const PictureOptions& o) {
  static constexpr Rgb track_colours[6] = {{0.85, 0.1, 0.1}, {0.1, 0.3, 0.9}, {0.0, 0.6, 0.2},
                                           {0.9, 0.5, 0.0},  {0.6, 0.1, 0.7}, {0.0, 0.6, 0.7}};
  cairo_t* cr = cv.cr;
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  // a path broken at a periodic boundary comes as several lines of one id: one colour, one dot
  std::size_t colour = 0;
  for (std::size_t k = 0; k < o.tracks.size(); ++k) {
    if (k > 0 && o.tracks[k].id != o.tracks[k - 1].id) ++colour;
    const auto& points = o.tracks[k].points;
    if (points.empty()) continue;
    const Rgb c = track_colours[colour % 6];
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_set_line_width(cr, 2.5);
    cairo_move_to(cr, cv.X(points.front().x), cv.Y(points.front().y));
    for (const Vec2& q : points) cairo_line_to(cr, cv.X(q.x), cv.Y(q.y));
    cairo_stroke(cr);
    if (k + 1 < o.tracks.size() && o.tracks[k + 1].id == o.tracks[k].id) continue;
    cairo_arc(cr, cv.X(points.back().x), cv.Y(points.back().y), 5.0, 0.0, 2.0 * std::numbers::pi);
    cairo_fill(cr);
  }
}

// The colour bar of a continuous colouring, with its range and unit, from (bx, by), bh high;
// faded as the grains are under chains or tracks (`alpha`), so that the bar reads them.
void draw_colour_bar(cairo_t* cr, SnapshotColour colour, double vmin, double vmax, double bx,
                     double by, double bh, double alpha) {
  cairo_push_group(cr); // drawn whole, then faded: its overlapping strips must not add up
  for (int k = 0; k < 100; ++k) {
    const Rgb c = ramp(1.0 - k / 99.0);
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_rectangle(cr, bx, by + bh * k / 100.0, 18.0, bh / 100.0 + 1.0);
    cairo_fill(cr);
  }
  cairo_pop_group_to_source(cr);
  cairo_paint_with_alpha(cr, alpha);
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  const double unit = colour == SnapshotColour::size ? 1e3 : 1.0;
  const char* label = colour == SnapshotColour::speed  ? "|v| m/s"
                      : colour == SnapshotColour::size ? "R mm"
                                                       : "|F| N";
  const std::string top = fmt::format("{:.3g}", vmax * unit),
                    bottom = fmt::format("{:.3g}", vmin * unit);
  cairo_move_to(cr, bx - 5.0, by - 8.0);
  cairo_show_text(cr, top.c_str());
  cairo_move_to(cr, bx - 5.0, by + bh + 16.0);
  cairo_show_text(cr, bottom.c_str());
  cairo_move_to(cr, bx - 10.0, by + bh + 32.0);
  cairo_show_text(cr, label);
}

// A legend of the categories (kinds or materials) present, from (bx, by).
void draw_legend(cairo_t* cr, const Frame& f, SnapshotColour colour, double bx, double by,
                 double alpha) {
  std::vector<std::size_t> present;
  for (std::size_t i = 0; i < f.position.size(); ++i) {
    const std::size_t k = colour == SnapshotColour::kind ? f.kind[i] : f.material[i];
    if (std::find(present.begin(), present.end(), k) == present.end()) present.push_back(k);
  }
  std::sort(present.begin(), present.end());
  static constexpr const char* kinds[3] = {"free", "fixed", "moved"};
  for (std::size_t m = 0; m < present.size() && m < 20; ++m) {
    const Rgb c = category(present[m]);
    cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
    cairo_rectangle(cr, bx - 10.0, by + 20.0 * static_cast<double>(m), 14.0, 14.0);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    const std::string name = colour == SnapshotColour::kind && present[m] < 3
                                 ? kinds[present[m]]
                                 : fmt::format("{}", present[m]);
    cairo_move_to(cr, bx + 8.0, by + 20.0 * static_cast<double>(m) + 12.0);
    cairo_show_text(cr, name.c_str());
  }
}

// A length scale in the top strip from (x, y): a bar of a round length near a fifth of the
// picture, with its length.
double draw_scale_bar(const Canvas& cv, double width_m, double x, double y) {
  const double target = 0.2 * width_m;
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  double length = decade;
  for (const double m : {2.0, 5.0})
    if (m * decade <= target) length = m * decade;
  const double px = length * cv.scale;
  cairo_set_source_rgb(cv.cr, 0.0, 0.0, 0.0);
  cairo_set_line_width(cv.cr, 2.0);
  cairo_move_to(cv.cr, x, y - 6.0);
  cairo_line_to(cv.cr, x, y);
  cairo_line_to(cv.cr, x + px, y);
  cairo_line_to(cv.cr, x + px, y - 6.0);
  cairo_stroke(cv.cr);
  const std::string label = length >= 1.0    ? fmt::format("{:g} m", length)
                            : length >= 1e-2 ? fmt::format("{:g} cm", length * 1e2)
                            : length >= 1e-3 ? fmt::format("{:g} mm", length * 1e3)
                                             : fmt::format("{:g} um", length * 1e6);
  cairo_move_to(cv.cr, x + px + 6.0, y);
  cairo_show_text(cv.cr, label.c_str());
  return x + px + 60.0;
}

// What a chain's width says: samples at a quarter, half and all of the force scale.
void draw_chain_key(const Canvas& cv, double f_max, double x, double y) {
  cairo_set_source_rgb(cv.cr, 0.0, 0.0, 0.0);
  cairo_move_to(cv.cr, x, y);
  cairo_show_text(cv.cr, "chains, normal force:");
  x += 130.0;
  for (const double u : {0.25, 0.5, 1.0}) {
    chain_pen(cv.cr, u);
    cairo_move_to(cv.cr, x, y - 4.0);
    cairo_line_to(cv.cr, x + 22.0, y - 4.0);
    cairo_stroke(cv.cr);
    cairo_set_source_rgb(cv.cr, 0.0, 0.0, 0.0);
    const std::string label = fmt::format("{:.3g} N", u * f_max);
    cairo_move_to(cv.cr, x + 27.0, y);
    cairo_show_text(cv.cr, label.c_str());
    x += 100.0;
  }
}

} // namespace

void write_frame_png(const Frame& f, const std::string& path, const PictureOptions& o) {
  const Rect box = o.bounds.value_or(frame_bounds(f));
  const Vec2 lo = box.lo, hi = box.hi;
  if (!(hi.x > lo.x && hi.y > lo.y)) throw std::runtime_error("nothing to draw in " + path);

  const double margin = 0.03 * (hi.x - lo.x);
  const double scale = (o.width_px - Canvas::bar_px) / (hi.x - lo.x + 2.0 * margin);
  // a strip of 40 px on top (time and count; length scale and chain key) and 20 px below
  int height_px = static_cast<int>(std::ceil((hi.y - lo.y + 2.0 * margin) * scale)) + 60;
  height_px += height_px % 2; // even sizes: what video encoders want
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, o.width_px, height_px);
  cairo_t* cr = cairo_create(surface);
  const Canvas cv{cr, lo, margin, scale, height_px};
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_paint(cr);

  const auto [vmin, vmax] = colour_range(f, o);
  draw_particles(cv, f, o, vmin, vmax);
  if (o.chains) draw_chains(cv, f, o);
  draw_walls(cv, f);
  draw_tracks(cv, o);

  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 12.0);
  const double bx = o.width_px - Canvas::bar_px + 15.0, by = 50.0, bh = height_px - 100.0;
  if (continuous(o.colour))
    draw_colour_bar(cr, o.colour, vmin, vmax, bx, by, bh, grain_alpha(o));
  else
    draw_legend(cr, f, o.colour, bx, by, grain_alpha(o));
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  const std::string stamp = fmt::format("t = {:.4f} s   N = {}", f.time, f.position.size());
  cairo_move_to(cr, 10.0, 16.0);
  cairo_show_text(cr, stamp.c_str());
  const double key_x = draw_scale_bar(cv, hi.x - lo.x, 10.0, 34.0);
  if (o.chains && chain_force_scale(f, o) > 0.0)
    draw_chain_key(cv, chain_force_scale(f, o), key_x, 34.0);

  cairo_destroy(cr);
  const cairo_status_t status = cairo_surface_write_to_png(surface, path.c_str());
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error("cannot write picture " + path + ": " +
                             cairo_status_to_string(status));
}

} // namespace talus
