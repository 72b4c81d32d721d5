#include "instruments/pattern_point.h"

#include <limits>

namespace tightfit {

std::optional<MaterialPoint> locate_on_panel(const SimulationMesh& mesh, int panel,
                                             const Vec2& rest_m) {
  // The triangle whose smallest barycentric coordinate is largest: inside when >= 0, and on a
  // shared edge either neighbour gives the same point.
  MaterialPoint best;
  double best_min = -std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (mesh.triangle_panel[t] != panel) continue;
    const auto& X = mesh.rest_triangles[t];
    Mat2 edges;
    edges << X[1] - X[0], X[2] - X[0];
    const Vec2 uv = edges.inverse() * (rest_m - X[0]);
    const Vec3 weights(1.0 - uv.x() - uv.y(), uv.x(), uv.y());
    if (weights.minCoeff() > best_min) {
      best_min = weights.minCoeff();
      best.triangle = static_cast<int>(t);
      best.barycentric = weights;
    }
  }
  if (best.triangle < 0 || best_min < -1e-9) return std::nullopt;
  return best;
}

Vec3 deformed_position(const SimulationMesh& mesh, const std::vector<Vec3>& positions_m,
                       const MaterialPoint& point) {
  const Triangle& t = mesh.triangles[point.triangle];
  return point.barycentric[0] * positions_m[t[0]] + point.barycentric[1] * positions_m[t[1]] +
         point.barycentric[2] * positions_m[t[2]];
}

double interpolate(const SimulationMesh& mesh, const std::vector<double>& field,
                   const MaterialPoint& point) {
  const Triangle& t = mesh.triangles[point.triangle];
  return point.barycentric[0] * field[t[0]] + point.barycentric[1] * field[t[1]] +
         point.barycentric[2] * field[t[2]];
}

std::pair<Vec2, Vec2> panel_extent_m(const SimulationMesh& mesh, int panel) {
  Vec2 low = Vec2::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (mesh.triangle_panel[t] != panel) continue;
    for (const Vec2& X : mesh.rest_triangles[t]) {
      low = low.cwiseMin(X);
      high = high.cwiseMax(X);
    }
  }
  return {low, high};
}

}  // namespace tightfit
