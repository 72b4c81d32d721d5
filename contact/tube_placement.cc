#include "contact/tube_placement.h"

#include "contact/axis_frame.h"
#include "core/tube_garment.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tightfit {

std::vector<Vec3> place_tube_round_axis(const Garment& garment, const SimulationMesh& mesh,
                                        const Vec3& centre_m, const Vec3& axis, double radius_m,
                                        double stretch) {
  const std::vector<RingCoordinate> ring = ring_coordinates(garment);
  if (ring.empty() || static_cast<int>(ring.size()) != mesh.n_unwelded_vertices())
    throw std::invalid_argument("garment '" + garment.name + "' is not a closed tube");
  if (!(axis.norm() > 0)) throw std::invalid_argument("the tube's axis must not be zero");
  const Vec3 a = axis.normalized();
  double v_min = mesh.layout_positions_m.front().y(), v_max = v_min;
  for (const Vec2& p : mesh.layout_positions_m) {
    v_min = std::min(v_min, p.y());
    v_max = std::max(v_max, p.y());
  }
  std::vector<Vec3> x(mesh.n_vertices);
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u) {
    const Vec2& p = mesh.layout_positions_m[u];
    const double angle = 2.0 * M_PI * ring[u].share;
    const double r = stretch > 0 ? stretch * ring[u].girth_m / (2.0 * M_PI) : radius_m;
    x[mesh.welded_index[u]] =
        centre_m + (p.y() - 0.5 * (v_min + v_max)) * a + r * radial_direction(a, angle);
  }
  return x;
}

std::vector<Vec3> place_tube_round_cylinder(const Garment& garment, const SimulationMesh& mesh,
                                            const Cylinder& cylinder, double radius_m) {
  return place_tube_round_axis(garment, mesh, cylinder.point_on_axis_m(), cylinder.axis(),
                               radius_m);
}

}  // namespace tightfit
