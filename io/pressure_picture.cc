#include "io/pressure_picture.h"

#include "core/units.h"
#include "io/raster_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace tightfit {

Vec3 viridis(double t) {
  // Nine samples of matplotlib's viridis (van der Walt and Smith, 2015), linearly interpolated.
  static const Vec3 samples[] = {
      {0.267, 0.005, 0.329}, {0.283, 0.141, 0.458}, {0.254, 0.265, 0.530}, {0.207, 0.372, 0.553},
      {0.164, 0.471, 0.558}, {0.128, 0.567, 0.551}, {0.135, 0.659, 0.518}, {0.267, 0.749, 0.441},
      {0.478, 0.821, 0.318}, {0.741, 0.873, 0.150}, {0.993, 0.906, 0.144}};
  constexpr int n = sizeof samples / sizeof samples[0];
  const double s = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * (n - 1);
  const int i = std::min(n - 2, static_cast<int>(s));
  return (1 - (s - i)) * samples[i] + (s - i) * samples[i + 1];
}

Vec3 above_top_colour() {
  return Vec3(0.85, 0.1, 0.1);
}

std::vector<std::array<Vec3, 2>> boundary_segments(const std::vector<Vec3>& points,
                                                   const std::vector<Triangle>& triangles) {
  std::map<std::pair<int, int>, int> uses;
  for (const Triangle& t : triangles)
    for (int c = 0; c < 3; ++c) {
      const int a = t[c], b = t[(c + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::array<Vec3, 2>> segments;
  for (const auto& [edge, n] : uses)
    if (n == 1) segments.push_back({points.at(edge.first), points.at(edge.second)});
  return segments;
}

namespace {

std::string label(double pressure_Pa) {
  char text[96];
  std::snprintf(text, sizeof text, "%.3g kPa  (%.3g mmHg)", pressure_Pa / 1000,
                units::to_mmHg(pressure_Pa));
  return text;
}

}  // namespace

void write_pressure_picture(const std::string& path, const PressureSurface& surface,
                            const PictureView& view, const PictureStyle& style) {
  write_pressure_panels(path, {surface}, {}, view, style);
}

void write_pressure_panels(const std::string& path, const std::vector<PressureSurface>& panels,
                           const std::vector<std::string>& captions, const PictureView& view,
                           const PictureStyle& style) {
  for (const PressureSurface& surface : panels)
    if (surface.pressure_Pa.size() != surface.points_m.size() ||
        surface.has_pressure.size() != surface.points_m.size())
      throw std::invalid_argument("picture '" + path + "': one pressure per point expected");
  if (!(view.direction.norm() > 0))
    throw std::invalid_argument("picture: the view direction is zero");
  const Vec3 forward = view.direction.normalized();
  const Vec3 up_across = view.up - view.up.dot(forward) * forward;
  if (!(up_across.norm() > 1e-9 * view.up.norm()))
    throw std::invalid_argument("picture: the up direction is along the view direction");
  const Vec3 up = up_across.normalized();
  const Vec3 right = forward.cross(up);
  const auto to_view = [&](const Vec3& x) { return Vec3(x.dot(right), x.dot(up), x.dot(forward)); };

  double largest_Pa = 0.0;
  bool outline = false;
  for (const PressureSurface& surface : panels) {
    for (std::size_t v = 0; v < surface.points_m.size(); ++v)
      if (surface.has_pressure[v]) largest_Pa = std::max(largest_Pa, surface.pressure_Pa[v]);
    outline = outline || !surface.outline_m.empty();
  }
  double top_Pa = style.top_pressure_Pa > 0 ? style.top_pressure_Pa : largest_Pa;
  if (!(top_Pa > 0)) top_Pa = 1.0;  // nothing presses: a bar from 0 to 1 Pa
  const bool clipped = largest_Pa > top_Pa;
  const bool legend = clipped || outline;

  // The colour bar takes the right-hand side; the panels share the rest side by side, below
  // the title and the legend (when there is one), above their captions (when there are any).
  const int bar_width = 24, label_room = 190, margin = 24, title_room = 40, legend_room = 26;
  const int caption_room = captions.empty() ? 0 : 24;
  RasterCanvas canvas(style.width, style.height, Vec3(1, 1, 1));
  const int area_x0 = margin, area_x1 = style.width - label_room - bar_width - 2 * margin;
  const int area_y0 = title_room + (legend ? legend_room : 0),
            area_y1 = style.height - margin - caption_room;
  const Vec3 grey(0.78, 0.78, 0.78);
  const int n_panels = static_cast<int>(panels.size());
  const double panel_width = n_panels > 0 ? double(area_x1 - area_x0) / n_panels : 0.0;

  // Each panel's extent in the view's plane; one scale for all, so that they compare.
  std::vector<Vec3> low(panels.size(), Vec3::Constant(1e300)),
      high(panels.size(), Vec3::Constant(-1e300));
  double scale = 1e300;
  for (int k = 0; k < n_panels; ++k) {
    const PressureSurface& surface = panels[k];
    for (const Vec3& x : surface.frame_m.empty() ? surface.points_m : surface.frame_m) {
      low[k] = low[k].cwiseMin(to_view(x));
      high[k] = high[k].cwiseMax(to_view(x));
    }
    const double span_x = std::max(high[k].x() - low[k].x(), 1e-12),
                 span_y = std::max(high[k].y() - low[k].y(), 1e-12);
    // A frame round chosen points, and panels side by side, keep a margin round them.
    const double fill = surface.frame_m.empty() && n_panels == 1 ? 1.0 : 0.9;
    scale = std::min(scale, fill * std::min(panel_width / span_x, (area_y1 - area_y0) / span_y));
  }

  for (int k = 0; k < n_panels && area_x1 > area_x0 && area_y1 > area_y0; ++k) {
    const PressureSurface& surface = panels[k];
    if (surface.points_m.empty()) continue;
    const int x0 = area_x0 + static_cast<int>(std::lround(k * panel_width)),
              x1 = area_x0 + static_cast<int>(std::lround((k + 1) * panel_width));
    canvas.set_clip(x0, area_y0, x1, area_y1);
    const double centre_x = 0.5 * (x0 + x1), centre_y = 0.5 * (area_y0 + area_y1);
    const Vec3 middle = 0.5 * (low[k] + high[k]);
    const auto to_screen = [&](const Vec3& s) {
      return Vec3(centre_x + scale * (s.x() - middle.x()), centre_y - scale * (s.y() - middle.y()),
                  s.z());
    };
    std::vector<Vec3> screen(surface.points_m.size());
    for (std::size_t v = 0; v < screen.size(); ++v)
      screen[v] = to_screen(to_view(surface.points_m[v]));
    for (const Triangle& t : surface.triangles) {
      const Vec3& a = surface.points_m[t[0]];
      const Vec3 normal = (surface.points_m[t[1]] - a).cross(surface.points_m[t[2]] - a);
      if (!(normal.norm() > 0)) continue;
      // Lit from the eye: a face seen edge-on is darker, so the shape reads.
      const double shade = 0.45 + 0.55 * std::abs(normal.normalized().dot(forward));
      canvas.fill_triangle({screen[t[0]], screen[t[1]], screen[t[2]]}, [&](const Vec3& l) {
        double covered = 0.0, pressure = 0.0;
        for (int c = 0; c < 3; ++c)
          if (surface.has_pressure[t[c]]) {
            covered += l[c];
            pressure += l[c] * surface.pressure_Pa[t[c]];
          }
        if (covered < 0.5) return Vec3(shade * grey);
        if (pressure / covered > top_Pa) return Vec3(shade * above_top_colour());
        return Vec3(shade * viridis(pressure / covered / top_Pa));
      });
    }
    for (const auto& [a, b] : surface.outline_m)
      canvas.draw_line(to_screen(to_view(a)), to_screen(to_view(b)), 2.0, Vec3(0.05, 0.05, 0.05),
                       surface.outline_depth_tolerance_m);
    if (k < static_cast<int>(captions.size()))
      canvas.draw_text(captions[k], static_cast<int>(std::lround(centre_x)), area_y1 + 18, 14,
                       RasterCanvas::Align::centre);
  }

  // The colour bar, top pressure at the top, five labelled ticks; above it, when the top cuts
  // off larger pressures, a swatch of the colour they are drawn in and the largest of them.
  const int bar_x0 = style.width - label_room - bar_width - margin, bar_x1 = bar_x0 + bar_width;
  const int bar_y0 = title_room + 20 + (clipped ? legend_room + 10 : 0),
            bar_y1 = style.height - margin - 10;
  for (int y = bar_y0; y < bar_y1; ++y)
    canvas.fill_rectangle(bar_x0, y, bar_x1, y + 1,
                          viridis(double(bar_y1 - 1 - y) / std::max(1, bar_y1 - bar_y0 - 1)));
  const int n_ticks = 5;
  for (int k = 0; k < n_ticks; ++k) {
    const double fraction = double(k) / (n_ticks - 1);
    const int y = static_cast<int>(std::lround(bar_y1 - 1 - fraction * (bar_y1 - 1 - bar_y0)));
    canvas.fill_rectangle(bar_x1, y, bar_x1 + 6, y + 1, Vec3::Zero());
    canvas.draw_text(label(fraction * top_Pa), bar_x1 + 9, y + 5, 13, RasterCanvas::Align::left);
  }
  if (clipped) {
    canvas.fill_rectangle(bar_x0, bar_y0 - legend_room - 4, bar_x1, bar_y0 - 6, above_top_colour());
    canvas.draw_text("up to " + label(largest_Pa), bar_x1 + 9, bar_y0 - 10, 13,
                     RasterCanvas::Align::left);
  }
  canvas.draw_text("pressure", bar_x0, bar_y0 - 8 - (clipped ? legend_room : 0), 14,
                   RasterCanvas::Align::left);

  // The legend: what grey, the dark line and the red mean.
  if (legend) {
    int x = margin;
    const int y = title_room + legend_room - 8;
    const auto entry = [&](const std::string& text) {
      canvas.draw_text(text, x, y, 13, RasterCanvas::Align::left);
      x += 7 * static_cast<int>(text.size()) + 24;  // about 7 px a character at 13 px
    };
    canvas.fill_rectangle(x, y - 12, x + 14, y + 2, grey);
    x += 20;
    entry(panels.empty() ? std::string("no garment on the skin") : panels.front().grey_means);
    if (outline) {
      canvas.fill_rectangle(x, y - 6, x + 22, y - 4, Vec3(0.05, 0.05, 0.05));
      x += 28;
      entry("garment's edge");
    }
    if (clipped) {
      canvas.fill_rectangle(x, y - 12, x + 14, y + 2, above_top_colour());
      x += 20;
      entry("above the bar's top");
    }
  }
  canvas.draw_text(style.title, margin, 26, 16, RasterCanvas::Align::left);
  canvas.write_png(path);
}

}  // namespace tightfit
