#include "massspring/flat_panel_placement.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tightfit {

std::vector<Vec3> place_panels_flat(const SimulationMesh& mesh, const Cylinder& cylinder,
                                    double distance_m) {
  const int n = mesh.n_unwelded_vertices();
  const int n_panels = static_cast<int>(mesh.panel_vertex_offset.size());
  if (n_panels < 2)
    throw std::invalid_argument(
        "mass spring: Placement = flat panels needs a garment of at least two panels, laid on "
        "opposite sides of the cylinder (paper Section 4.3)");
  auto panel_end = [&](int p) { return p + 1 < n_panels ? mesh.panel_vertex_offset[p + 1] : n; };

  double v_min = mesh.layout_positions_m.front().y(), v_max = v_min;
  for (const Vec2& q : mesh.layout_positions_m) {
    v_min = std::min(v_min, q.y());
    v_max = std::max(v_max, q.y());
  }
  std::vector<double> u_centre(n_panels);
  double circumference_m = 0.0;
  for (int p = 0; p < n_panels; ++p) {
    double u_min = mesh.layout_positions_m[mesh.panel_vertex_offset[p]].x(), u_max = u_min;
    for (int u = mesh.panel_vertex_offset[p]; u < panel_end(p); ++u) {
      u_min = std::min(u_min, mesh.layout_positions_m[u].x());
      u_max = std::max(u_max, mesh.layout_positions_m[u].x());
    }
    u_centre[p] = 0.5 * (u_min + u_max);
    circumference_m += u_max - u_min;
  }

  const Vec3& axis = cylinder.axis();
  const Vec3 e1 = cylinder.reference_direction();
  const Vec3 e2 = axis.cross(e1);
  std::vector<Vec3> x(n);
  for (int p = 0; p < n_panels; ++p) {
    const double angle = 2.0 * M_PI * u_centre[p] / circumference_m;
    const Vec3 normal = std::cos(angle) * e1 + std::sin(angle) * e2;
    // (axis x n) x axis = n: a counter-clockwise layout triangle keeps an outward normal.
    const Vec3 round = axis.cross(normal);
    const Vec3 centre = cylinder.point_on_axis_m() + distance_m * normal;
    for (int u = mesh.panel_vertex_offset[p]; u < panel_end(p); ++u) {
      const Vec2& q = mesh.layout_positions_m[u];
      x[u] = centre + (q.x() - u_centre[p]) * round + (q.y() - 0.5 * (v_min + v_max)) * axis;
    }
  }
  return x;
}

}  // namespace tightfit
