#include "core/tapered_tube_garment.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tightfit {

PiecewiseLinear::PiecewiseLinear(std::vector<Point> points, const std::string& what)
    : points_(std::move(points)) {
  if (points_.empty()) throw std::invalid_argument(what + ": no height:value point given");
  for (std::size_t k = 1; k < points_.size(); ++k)
    if (!(points_[k].height_m > points_[k - 1].height_m))
      throw std::invalid_argument(what + ": the heights must increase from point to point");
}

double PiecewiseLinear::at(double height_m) const {
  if (points_.empty()) return 0.0;
  if (height_m <= points_.front().height_m) return points_.front().value;
  if (height_m >= points_.back().height_m) return points_.back().value;
  const auto upper = std::upper_bound(points_.begin(), points_.end(), height_m,
                                      [](double h, const Point& p) { return h < p.height_m; });
  const Point& b = *upper;
  const Point& a = *(upper - 1);
  const double s = (height_m - a.height_m) / (b.height_m - a.height_m);
  return a.value + s * (b.value - a.value);
}

double TaperedTubeShape::relaxed_girth_m(double height_m) const {
  const double ease = negative_ease.points().empty() ? 0.0 : negative_ease.at(height_m);
  return girths_m.at(height_m) * (1.0 - ease);
}

void TaperedTubeShape::validate() const {
  if (!(length_m > 0)) throw std::invalid_argument("Length must be positive (m)");
  if (n_panels < 1) throw std::invalid_argument("Number of panels must be at least 1");
  const auto inside = [&](const PiecewiseLinear& f, const std::string& entry) {
    for (const auto& p : f.points())
      if (!(p.height_m >= 0 && p.height_m <= length_m))
        throw std::invalid_argument(entry + ": height " + std::to_string(p.height_m) +
                                    " m lies outside the tube (0 to Length, " +
                                    std::to_string(length_m) + " m)");
  };
  if (girths_m.points().empty()) throw std::invalid_argument("Girths: no height:girth given");
  inside(girths_m, "Girths");
  inside(negative_ease, "Negative ease");
  for (const auto& p : girths_m.points())
    if (!(p.value > 0))
      throw std::invalid_argument("Girths: the girth at height " + std::to_string(p.height_m) +
                                  " m must be positive (m)");
  for (const auto& p : negative_ease.points())
    if (!(p.value > -1 && p.value < 1))
      throw std::invalid_argument("Negative ease: the ease at height " +
                                  std::to_string(p.height_m) + " m must lie in (-1, 1)");
}

Garment make_tapered_tube_garment(const std::string& name, const TaperedTubeShape& shape,
                                  const MeshSpacing& spacing) {
  shape.validate();
  spacing.validate();
  const int n = shape.n_panels;
  // The mean and widest relaxed panel width, sampled finely enough to see every knot.
  double widest_m = 0.0, sum_m = 0.0;
  const int samples = 1000;
  for (int k = 0; k <= samples; ++k) {
    const double w = shape.relaxed_girth_m(shape.length_m * k / samples) / n;
    widest_m = std::max(widest_m, w);
    sum_m += w;
  }
  const double mean_m = sum_m / (samples + 1);
  Garment garment;
  garment.name = name;
  for (int p = 0; p < n; ++p) {
    Panel panel = make_rectangle_panel(name + " panel " + std::to_string(p + 1), mean_m,
                                       shape.length_m, spacing);
    for (Vec2& x : panel.rest_positions_m) {
      const double width_m = shape.relaxed_girth_m(x.y()) / n;
      x.x() = 0.5 * widest_m + (x.x() / mean_m - 0.5) * width_m;
    }
    panel.layout_offset_m = Vec2(p * widest_m, 0.0);
    garment.panels.push_back(std::move(panel));
    garment.seams.push_back({p, "right", (p + 1) % n, "left"});
  }
  return garment;
}

}  // namespace tightfit
