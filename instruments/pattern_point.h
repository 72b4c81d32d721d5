// A point printed on a panel, found on the welded mesh: the triangle of the panel that holds it
// in pattern space and its barycentric coordinates there, so that it can be followed onto the
// deformed garment (a material point).
#pragma once

#include "core/garment.h"

#include <optional>

namespace tightfit {

struct MaterialPoint {
  int triangle = -1;                // index into SimulationMesh::triangles
  Vec3 barycentric = Vec3::Zero();  // weights of the triangle's three corners
};

// The material point at `rest_m` of panel `panel`, in the panel's grain axes (x weft, y warp,
// metres: SimulationMesh::rest_triangles); none when the point is outside the panel.
std::optional<MaterialPoint> locate_on_panel(const SimulationMesh& mesh, int panel,
                                             const Vec2& rest_m);

// Where a material point is now, and a per-vertex field there (linear over the triangle).
Vec3 deformed_position(const SimulationMesh& mesh, const std::vector<Vec3>& positions_m,
                       const MaterialPoint& point);
double interpolate(const SimulationMesh& mesh, const std::vector<double>& field,
                   const MaterialPoint& point);

// The box a panel covers in its grain axes, m: lower-left and upper-right corners.
std::pair<Vec2, Vec2> panel_extent_m(const SimulationMesh& mesh, int panel);

}  // namespace tightfit
