#include "bodies/panel_wrap.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tightfit {

double ellipse_perimeter_m(double a_m, double b_m) {
  const double h = (a_m - b_m) * (a_m - b_m) / ((a_m + b_m) * (a_m + b_m));
  return M_PI * (a_m + b_m) * (1.0 + 3.0 * h / (10.0 + std::sqrt(4.0 - 3.0 * h)));
}

std::vector<Vec3> wrap_panels_round_axis(const Garment& garment, const SimulationMesh& mesh,
                                         const PanelWrap& wrap) {
  if (!(wrap.axis.norm() > 0)) throw std::invalid_argument("the axis must not be zero");
  const Vec3 axis = wrap.axis.normalized();
  const Vec3 front_normal = wrap.front - wrap.front.dot(axis) * axis;
  if (!(front_normal.norm() > 1e-9 * wrap.front.norm()))
    throw std::invalid_argument("the front direction must not lie along the axis");
  const Vec3 f = front_normal.normalized();
  const Vec3 l = axis.cross(f);
  const double a = wrap.semi_axis_side_m, b = wrap.semi_axis_front_m;
  if (!(a > 0 && b > 0)) throw std::invalid_argument("the semi-axes must be positive (m)");
  if (wrap.panel_angles_rad.size() != garment.panels.size())
    throw std::invalid_argument(
        "one angle per panel is needed: " + std::to_string(wrap.panel_angles_rad.size()) + " for " +
        std::to_string(garment.panels.size()) + " panels");
  if (!wrap.panel_hem_heights_m.empty() && wrap.panel_hem_heights_m.size() != garment.panels.size())
    throw std::invalid_argument(
        "one hem height per panel is needed: " + std::to_string(wrap.panel_hem_heights_m.size()) +
        " for " + std::to_string(garment.panels.size()) + " panels");
  const double radius = ellipse_perimeter_m(a, b) / (2.0 * M_PI);

  std::vector<Vec3> x(mesh.n_unwelded_vertices());
  for (std::size_t p = 0; p < garment.panels.size(); ++p) {
    const std::vector<Vec2>& rest = garment.panels[p].rest_positions_m;
    if (rest.empty()) continue;
    double x_min = rest.front().x(), x_max = x_min, y_min = rest.front().y();
    for (const Vec2& r : rest) {
      x_min = std::min(x_min, r.x());
      x_max = std::max(x_max, r.x());
      y_min = std::min(y_min, r.y());
    }
    const double x_middle = 0.5 * (x_min + x_max);
    const double hem_m =
        wrap.panel_hem_heights_m.empty() ? wrap.hem_height_m : wrap.panel_hem_heights_m[p];
    for (std::size_t i = 0; i < rest.size(); ++i) {
      const double phi = wrap.panel_angles_rad[p] + (rest[i].x() - x_middle) / radius;
      x[mesh.panel_vertex_offset[p] + i] = wrap.centre_m + (hem_m + rest[i].y() - y_min) * axis +
                                           b * std::cos(phi) * f + a * std::sin(phi) * l;
    }
  }
  return x;
}

}  // namespace tightfit
