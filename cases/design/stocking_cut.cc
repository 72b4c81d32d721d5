#include "cases/design/stocking_cut.h"

#include "io/csv_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace tightfit {

std::vector<CutKnot> design_cut(const PiecewiseLinear& limb_girths_m,
                                const std::vector<NamedValue>& points,
                                const std::vector<double>& circumferences_m) {
  std::vector<PiecewiseLinear::Point> ease;
  for (std::size_t k = 0; k < points.size(); ++k)
    ease.push_back(
        {points[k].value, 1.0 - circumferences_m[k] / limb_girths_m.at(points[k].value)});
  const PiecewiseLinear ease_at(ease, "the design's negative ease");
  std::vector<CutKnot> knots;
  for (const auto& g : limb_girths_m.points()) knots.push_back({g.height_m, 0, 0, ""});
  for (const NamedValue& p : points) {
    auto same = std::find_if(knots.begin(), knots.end(), [&](const CutKnot& k) {
      return std::abs(k.height_m - p.value) < 1e-9;
    });
    if (same == knots.end()) same = knots.insert(knots.end(), {p.value, 0, 0, ""});
    same->point = p.name;
  }
  std::sort(knots.begin(), knots.end(),
            [](const CutKnot& a, const CutKnot& b) { return a.height_m < b.height_m; });
  for (CutKnot& k : knots) {
    k.girth_m = limb_girths_m.at(k.height_m);
    k.circumference_m = k.girth_m * (1.0 - ease_at.at(k.height_m));
  }
  return knots;
}

std::string relaxed_girths_setting(const std::vector<CutKnot>& knots) {
  std::string text;
  char piece[64];
  // Every digit a double holds: the last knot is the tube's length, which the case checks the
  // heights against (a rounded length can lie beyond it).
  for (const CutKnot& k : knots) {
    std::snprintf(piece, sizeof piece, "%s%.17g:%.17g", text.empty() ? "" : ", ", k.height_m,
                  k.circumference_m);
    text += piece;
  }
  return text;
}

void write_cut_csv(const std::string& path, const std::vector<CutKnot>& knots) {
  CsvTable table(path, {"height_m", "girth_m", "circumference_m", "negative_ease", "point"});
  for (const CutKnot& k : knots)
    table.write_row(
        {k.height_m, k.girth_m, k.circumference_m, 1.0 - k.circumference_m / k.girth_m, k.point});
}

CutOutline cut_outline(const std::vector<CutKnot>& knots) {
  CutOutline outline;
  double widest_mm = 0.0;
  for (const CutKnot& k : knots) widest_mm = std::max(widest_mm, 1e3 * k.circumference_m);
  const double middle = 0.5 * widest_mm;
  const int n = static_cast<int>(knots.size());
  // Up the right side, then down the left: counter-clockwise with y up.
  outline.points_mm.emplace_back(middle - 500 * knots.front().circumference_m,
                                 1e3 * knots.front().height_m);
  for (int i = 0; i < n; ++i)
    outline.points_mm.emplace_back(middle + 500 * knots[i].circumference_m,
                                   1e3 * knots[i].height_m);
  for (int i = n - 1; i > 0; --i)
    outline.points_mm.emplace_back(middle - 500 * knots[i].circumference_m,
                                   1e3 * knots[i].height_m);
  outline.corners = {0, 1, n, n + 1};
  outline.width_mm = widest_mm;
  outline.height_mm = 1e3 * (knots.back().height_m - knots.front().height_m);
  return outline;
}

void write_cut_svg(const std::string& path, const std::string& piece,
                   const std::vector<CutKnot>& knots) {
  const CutOutline outline = cut_outline(knots);
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write '" + path + "'");
  // Room on the right for the points' labels ("G 33.1 cm", 9 mm type: about 45 mm).
  const double margin = 20, labels = 50;
  const double w = outline.width_mm + 2 * margin + labels, h = outline.height_mm + 2 * margin;
  // SVG's y points down: the top of the garment is at the top of the drawing.
  const auto x = [&](const Vec2& p) { return p.x() + margin; };
  const auto y = [&](const Vec2& p) { return margin + outline.height_mm - p.y(); };
  char line[200];
  std::snprintf(line, sizeof line,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.1fmm\" height=\"%.1fmm\" "
                "viewBox=\"0 0 %.1f %.1f\">\n",
                w, h, w, h);
  out << line
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<path class=\"fabric\" id=\""
      << piece << "\" fill=\"#e8eef8\" stroke=\"black\" stroke-width=\"0.8\" d=\"";
  for (std::size_t i = 0; i < outline.points_mm.size(); ++i) {
    std::snprintf(line, sizeof line, "%s%.3f %.3f ", i == 0 ? "M " : "L ", x(outline.points_mm[i]),
                  y(outline.points_mm[i]));
    out << line;
  }
  out << "Z\"/>\n";
  // The measuring points: a line across the piece and the point's name.
  for (const CutKnot& k : knots) {
    if (k.point.empty()) continue;
    const double half = 500 * k.circumference_m, mid = 0.5 * outline.width_mm;
    const Vec2 a(mid - half, 1e3 * k.height_m), b(mid + half, 1e3 * k.height_m);
    std::snprintf(line, sizeof line,
                  "<line x1=\"%.3f\" y1=\"%.3f\" x2=\"%.3f\" y2=\"%.3f\" stroke=\"#c03030\" "
                  "stroke-width=\"0.5\" stroke-dasharray=\"4 2\"/>\n",
                  x(a), y(a), x(b), y(b));
    out << line;
    std::snprintf(line, sizeof line,
                  "<text x=\"%.3f\" y=\"%.3f\" font-size=\"9\" font-family=\"sans-serif\" "
                  "fill=\"#c03030\">%s %.1f cm</text>\n",
                  x(b) + 3, y(b) + 3, k.point.c_str(), 100 * k.circumference_m);
    out << line;
  }
  // The grain (warp) along the middle.
  const Vec2 g0(0.5 * outline.width_mm, 0.1 * outline.height_mm),
      g1(0.5 * outline.width_mm, 0.9 * outline.height_mm);
  std::snprintf(line, sizeof line,
                "<line x1=\"%.3f\" y1=\"%.3f\" x2=\"%.3f\" y2=\"%.3f\" stroke=\"#404040\" "
                "stroke-width=\"0.5\"/>\n</svg>\n",
                x(g0), y(g0), x(g1), y(g1));
  out << line;
  if (!out) throw std::runtime_error("cannot write '" + path + "'");
}

}  // namespace tightfit
