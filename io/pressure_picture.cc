#include "io/pressure_picture.h"

#include "core/units.h"
#include "io/raster_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
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
  const std::size_t n = surface.points_m.size();
  if (surface.pressure_Pa.size() != n || surface.has_pressure.size() != n)
    throw std::invalid_argument("picture '" + path + "': one pressure per point expected");
  if (!(view.direction.norm() > 0))
    throw std::invalid_argument("picture: the view direction is zero");
  const Vec3 forward = view.direction.normalized();
  const Vec3 up_across = view.up - view.up.dot(forward) * forward;
  if (!(up_across.norm() > 1e-9 * view.up.norm()))
    throw std::invalid_argument("picture: the up direction is along the view direction");
  const Vec3 up = up_across.normalized();
  const Vec3 right = forward.cross(up);

  // The colour bar takes the right-hand side; the surface is fitted into the rest.
  const int bar_width = 24, label_room = 190, margin = 24, title_room = 40;
  RasterCanvas canvas(style.width, style.height, Vec3(1, 1, 1));
  const int area_x0 = margin, area_x1 = style.width - label_room - bar_width - 2 * margin;
  const int area_y0 = title_room, area_y1 = style.height - margin;
  double top_Pa = style.top_pressure_Pa;
  if (!(top_Pa > 0))
    for (std::size_t v = 0; v < n; ++v)
      if (surface.has_pressure[v]) top_Pa = std::max(top_Pa, surface.pressure_Pa[v]);
  if (!(top_Pa > 0)) top_Pa = 1.0;  // nothing presses: a bar from 0 to 1 Pa

  if (n > 0 && area_x1 > area_x0 && area_y1 > area_y0) {
    std::vector<Vec3> screen(n);
    Vec3 low = Vec3::Constant(1e300), high = Vec3::Constant(-1e300);
    for (std::size_t v = 0; v < n; ++v) {
      const Vec3& x = surface.points_m[v];
      screen[v] = Vec3(x.dot(right), x.dot(up), x.dot(forward));
      low = low.cwiseMin(screen[v]);
      high = high.cwiseMax(screen[v]);
    }
    const double span_x = std::max(high.x() - low.x(), 1e-12),
                 span_y = std::max(high.y() - low.y(), 1e-12);
    const double scale = std::min((area_x1 - area_x0) / span_x, (area_y1 - area_y0) / span_y);
    const double centre_x = 0.5 * (area_x0 + area_x1), centre_y = 0.5 * (area_y0 + area_y1);
    for (Vec3& s : screen)
      s = Vec3(centre_x + scale * (s.x() - 0.5 * (low.x() + high.x())),
               centre_y - scale * (s.y() - 0.5 * (low.y() + high.y())), s.z());
    const Vec3 grey(0.78, 0.78, 0.78);
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
        return Vec3(shade * viridis(pressure / covered / top_Pa));
      });
    }
  }

  // The colour bar, top pressure at the top, five labelled ticks.
  const int bar_x0 = style.width - label_room - bar_width - margin, bar_x1 = bar_x0 + bar_width;
  const int bar_y0 = title_room + 20, bar_y1 = style.height - margin - 10;
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
  canvas.draw_text("pressure", bar_x0, bar_y0 - 8, 14, RasterCanvas::Align::left);
  canvas.draw_text(style.title, margin, 26, 16, RasterCanvas::Align::left);
  canvas.write_png(path);
}

}  // namespace tightfit
