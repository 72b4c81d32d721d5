// Triangulates a rectangular panel with well-shaped (Delaunay) triangles.
#pragma once

#include "core/garment.h"

namespace tightfit {

// Target spacing of a panel mesh, metres. Along x (the weft: round the body for a tube) the
// spacing sets how closely the straight edges follow the body's curvature; along y it can be
// coarser. See docs/model.md ("Mesh") for the chord error this controls.
struct MeshSpacing {
  double along_x_m = 0.0088;
  double along_y_m = 0.020;
  void validate() const;  // throws std::invalid_argument unless both are positive
};

// A width x height rectangle, lower-left corner at the origin, meshed in rows of constant y
// (row spacing ~ along_y_m) whose vertices are spaced ~ along_x_m; every other row is shifted
// by half a spacing and closed by a vertex on each side edge, so every triangle is acute (its
// circumcircle holds no other vertex: a Delaunay triangulation).
// Edges: "bottom" and "top" (left to right), "left" and "right" (bottom to top).
Panel make_rectangle_panel(const std::string& name, double width_m, double height_m,
                           const MeshSpacing& spacing);

}  // namespace tightfit
