#include "body/body_picture.h"

#include "io/raster_canvas.h"

#include <algorithm>
#include <cmath>

namespace tightfit {

namespace {

// An orthographic view: a point's pixel (x, y) and depth (smaller nearer the eye).
struct View {
  Vec3 forward, right, up = Vec3::UnitZ();
  double scale = 1.0;  // pixels per metre
  Vec2 origin;         // the pixel of the world's (right . x, up . x) = (0, 0)
  Vec3 pixel(const Vec3& x) const {
    return Vec3(origin.x() + scale * right.dot(x), origin.y() - scale * up.dot(x), forward.dot(x));
  }
};

void draw_segment(RasterCanvas& canvas, const Vec3& a, const Vec3& b, double half_width,
                  const Vec3& colour) {
  Vec2 n(b.y() - a.y(), a.x() - b.x());
  if (!(n.norm() > 0)) return;
  n *= half_width / n.norm();
  const Vec3 o(n.x(), n.y(), 0);
  const auto flat = [&](const Vec3&) { return colour; };
  canvas.fill_triangle({a - o, a + o, b + o}, flat);
  canvas.fill_triangle({a - o, b + o, b - o}, flat);
}

}  // namespace

void write_body_picture(const std::string& path, const TriangleSurface& surface,
                        const BodyMeasurements& m, const std::string& title) {
  const int width = 1400, height = 1000, title_room = 40, margin = 20, label_room = 220;
  RasterCanvas canvas(width, height, Vec3(1, 1, 1));
  canvas.draw_text(title, width / 2, 28, 18, RasterCanvas::Align::centre);
  Vec3 lo = surface.vertices_m.front(), hi = lo;
  for (const Vec3& x : surface.vertices_m) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  // Front (the eye at -y, the body's left on the picture's right) and left side (the eye at
  // +x, the front on the left), side by side, one scale.
  View views[2];
  views[0].forward = Vec3::UnitY();
  views[1].forward = -Vec3::UnitX();
  const double room_w = 0.5 * (width - label_room) - 2 * margin;
  const double room_h = height - title_room - 2 * margin;
  double scale = room_h / (hi.z() - lo.z());
  scale = std::min(scale, room_w / (hi.x() - lo.x()));
  scale = std::min(scale, room_w / (hi.y() - lo.y()));
  for (int i = 0; i < 2; ++i) {
    View& v = views[i];
    v.right = v.forward.cross(v.up);
    v.scale = scale;
    const Vec3 centre = 0.5 * (lo + hi);
    const double x0 = label_room + margin + (i + 0.5) * (room_w + 2 * margin) - margin;
    v.origin = Vec2(x0 - scale * v.right.dot(centre), title_room + margin + scale * hi.z());
    canvas.draw_text(i == 0 ? "front" : "left side", static_cast<int>(x0), height - 6, 14,
                     RasterCanvas::Align::centre);
  }
  for (const View& v : views) {
    for (const Triangle& t : surface.triangles) {
      const Vec3& a = surface.vertices_m[t[0]];
      const Vec3& b = surface.vertices_m[t[1]];
      const Vec3& c = surface.vertices_m[t[2]];
      const Vec3 normal = (b - a).cross(c - a);
      if (!(normal.norm() > 0)) continue;
      const double light = 0.35 + 0.6 * std::abs(normal.normalized().dot(v.forward));
      const Vec3 grey(light, light, light);
      canvas.fill_triangle({v.pixel(a), v.pixel(b), v.pixel(c)}, [&](const Vec3&) { return grey; });
    }
    // The tape lines just in front of the surface: hidden where the body is in front of them.
    const Vec3 tape(0.1, 0.35, 0.85);
    for (const BodyGirth& g : m.girths)
      for (std::size_t i = 0; i < g.hull_m.size(); ++i) {
        Vec3 a = v.pixel(g.hull_m[i]), b = v.pixel(g.hull_m[(i + 1) % g.hull_m.size()]);
        a.z() -= 0.004;
        b.z() -= 0.004;
        draw_segment(canvas, a, b, 1.2, tape);
      }
    for (const BodyLandmark& l : m.landmarks) {
      const Vec3 p = v.pixel(l.point_m);
      canvas.fill_rectangle(static_cast<int>(p.x()) - 3, static_cast<int>(p.y()) - 3,
                            static_cast<int>(p.x()) + 4, static_cast<int>(p.y()) + 4,
                            Vec3(0.85, 0.1, 0.1));
    }
  }
  // The torso's girths named at their height, left of the front view.
  for (const BodyGirth& g : m.girths) {
    if (g.name.find("left") != std::string::npos || g.name.find("right") != std::string::npos)
      continue;
    const Vec3 p = views[0].pixel(g.centre_m);
    char text[96];
    std::snprintf(text, sizeof text, "%s %.1f cm", g.name.c_str(), 100 * g.girth_m);
    canvas.draw_text(text, label_room - 10, static_cast<int>(p.y()) + 5, 14,
                     RasterCanvas::Align::right);
  }
  canvas.write_png(path);
}

}  // namespace tightfit
