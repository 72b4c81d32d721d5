#include "io/outline_picture.h"

#include "io/raster_canvas.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace tightfit {

Vec3 seam_colour(int number) {
  // Eight colours told apart by most readers (Okabe and Ito, 2008), then round again.
  static const Vec3 colours[] = {{0.90, 0.62, 0.00}, {0.34, 0.71, 0.91}, {0.00, 0.62, 0.45},
                                 {0.80, 0.47, 0.65}, {0.00, 0.45, 0.70}, {0.84, 0.37, 0.00},
                                 {0.94, 0.89, 0.26}, {0.35, 0.35, 0.35}};
  return colours[(std::max(number, 1) - 1) % 8];
}

namespace {

bool overlap(const PlacedLabel& a, const PlacedLabel& b, int font_px) {
  const double half_widths = 0.3 * font_px * (a.text.size() + b.text.size());
  return std::abs(a.x - b.x) < half_widths + 2 && std::abs(a.y - b.y) < font_px;
}

}  // namespace

std::vector<PlacedLabel> labels_without_overlap(const std::vector<PlacedLabel>& labels,
                                                int font_px) {
  std::vector<PlacedLabel> kept;
  for (PlacedLabel label : labels) {
    const bool repeated = std::any_of(kept.begin(), kept.end(), [&](const PlacedLabel& k) {
      return k.text == label.text && std::hypot(k.x - label.x, k.y - label.y) < 2.0 * font_px;
    });
    if (repeated) continue;
    for (int moves = 0; moves < 8; ++moves) {
      const bool clash = std::any_of(kept.begin(), kept.end(), [&](const PlacedLabel& k) {
        return overlap(k, label, font_px);
      });
      if (!clash) break;
      label.y += font_px;
    }
    kept.push_back(label);
  }
  return kept;
}

void write_outline_picture(const std::string& path, const OutlineDrawing& drawing, int width,
                           int height) {
  RasterCanvas canvas(width, height, Vec3(1, 1, 1));
  const int margin = 40, title_room = 50, scale_room = 40;
  Vec2 low = Vec2::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const auto& panel : drawing.panels)
    for (const auto& line : panel.edges_m)
      for (const Vec2& x : line) {
        low = low.cwiseMin(x);
        high = high.cwiseMax(x);
      }
  if (!(high.x() >= low.x())) low = high = Vec2::Zero();
  const double span_x = std::max(high.x() - low.x(), 1e-9),
               span_y = std::max(high.y() - low.y(), 1e-9);
  const int x0 = margin, x1 = width - margin, y0 = title_room + margin / 2,
            y1 = height - scale_room - margin / 2;
  const double scale = std::min((x1 - x0) / span_x, (y1 - y0) / span_y);  // pixels a metre
  const Vec2 centre = 0.5 * (low + high);
  // Layout y upwards, picture y downwards.
  const auto to_screen = [&](const Vec2& x) {
    return Vec3(0.5 * (x0 + x1) + scale * (x.x() - centre.x()),
                0.5 * (y0 + y1) - scale * (x.y() - centre.y()), 0.0);
  };
  const auto polyline = [&](const std::vector<Vec2>& line, double line_width, const Vec3& colour) {
    for (std::size_t k = 1; k < line.size(); ++k)
      canvas.draw_line(to_screen(line[k - 1]), to_screen(line[k]), line_width, colour,
                       std::numeric_limits<double>::infinity());
  };
  for (const auto& panel : drawing.panels)
    for (const auto& line : panel.edges_m) polyline(line, 2.0, Vec3(0.55, 0.55, 0.55));

  // The seams, and one label per sewn edge, set inside the panel from the edge's middle.
  std::map<std::pair<int, std::string>,
           std::pair<std::vector<int>, const OutlineDrawing::SeamEdge*>>
      labels;
  for (const auto& e : drawing.seam_edges) {
    polyline(e.points_m, 4.0, seam_colour(e.seam));
    auto& [numbers, edge] = labels[{e.panel, e.edge}];
    numbers.push_back(e.seam);
    edge = &e;
  }
  std::vector<Vec2> panel_middle(drawing.panels.size(), Vec2::Zero()),
      panel_size(drawing.panels.size(), Vec2::Zero());
  for (std::size_t p = 0; p < drawing.panels.size(); ++p) {
    Vec2 a = Vec2::Constant(std::numeric_limits<double>::infinity()), b = -a;
    for (const auto& line : drawing.panels[p].edges_m)
      for (const Vec2& x : line) {
        a = a.cwiseMin(x);
        b = b.cwiseMax(x);
      }
    if (b.x() >= a.x()) panel_middle[p] = 0.5 * (a + b), panel_size[p] = b - a;
  }
  std::vector<PlacedLabel> placed;
  for (auto& [key, entry] : labels) {
    auto& [numbers, edge] = entry;
    if (edge->points_m.empty()) continue;
    std::sort(numbers.begin(), numbers.end());
    numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
    std::string text;
    for (int n : numbers) text += (text.empty() ? "" : ", ") + std::to_string(n);
    const Vec2 mid = edge->points_m[edge->points_m.size() / 2];
    Vec2 inward = key.first >= 0 && key.first < static_cast<int>(panel_middle.size())
                      ? Vec2(panel_middle[key.first] - mid)
                      : Vec2::Zero();
    inward = inward.norm() > 0 ? Vec2(inward.normalized()) : Vec2::Zero();
    const Vec3 at = to_screen(mid);
    // 22 px inside the panel; picture y runs downwards.
    placed.push_back({text, static_cast<int>(std::lround(at.x() + 22 * inward.x())),
                      static_cast<int>(std::lround(at.y() - 22 * inward.y() + 6))});
  }
  for (const PlacedLabel& label : labels_without_overlap(placed, 16))
    canvas.draw_text(label.text, label.x, label.y, 16, RasterCanvas::Align::centre);
  // A name in the middle of its panel; below it, smaller, where the panel is narrower than the
  // name (a binding strip), every other one a line lower so that neighbours do not overlap.
  int below = 0;
  for (std::size_t p = 0; p < drawing.panels.size(); ++p) {
    const std::string& name = drawing.panels[p].name;
    const double name_width_px = 0.6 * 24 * name.size();  // about, for a 24 px font
    Vec3 at = to_screen(panel_middle[p]);
    int size = 24;
    if (scale * panel_size[p].x() < name_width_px) {
      at = to_screen(panel_middle[p] - Vec2(0, 0.5 * panel_size[p].y()));
      at.y() += 20 + 16 * (below++ % 2);
      size = 14;
    }
    canvas.draw_text(name, static_cast<int>(std::lround(at.x())),
                     static_cast<int>(std::lround(at.y())), size, RasterCanvas::Align::centre);
  }

  // A 100 mm scale bar, bottom left.
  const int bar_length = static_cast<int>(std::lround(0.1 * scale));
  const int bar_y = height - margin / 2 - 8;
  canvas.fill_rectangle(margin, bar_y - 3, margin + bar_length, bar_y, Vec3::Zero());
  canvas.draw_text("100 mm", margin + bar_length + 8, bar_y + 2, 14, RasterCanvas::Align::left);
  canvas.draw_text(drawing.title, margin, 32, 18, RasterCanvas::Align::left);
  canvas.write_png(path);
}

}  // namespace tightfit
