#include "massspring/sewn_tube_placement.h"

#include <cmath>
#include <stdexcept>

namespace tightfit {

std::vector<Vec3> sewn_tube_positions(const SimulationMesh& mesh, double circumference_m,
                                      double height_m, double radius_m) {
  if (!(circumference_m > 0) || !(radius_m > 0))
    throw std::invalid_argument("sewn tube: circumference and radius must be positive (m)");
  std::vector<Vec3> x(mesh.n_vertices, Vec3::Zero());
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u) {
    const Vec2& p = mesh.layout_positions_m[u];
    const double angle = 2.0 * M_PI * p.x() / circumference_m;
    x[mesh.welded_index[u]] =
        Vec3(radius_m * std::cos(angle), radius_m * std::sin(angle), p.y() - 0.5 * height_m);
  }
  return x;
}

}  // namespace tightfit
