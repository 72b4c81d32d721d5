// Triangulates a rectangular panel with well-shaped (Delaunay) triangles.
#pragma once

#include "core/garment.h"

namespace tightfit {

// Target spacing of a panel mesh, metres. Along x (the weft: round the body for a tube) the
// spacing sets how closely the straight edges follow the body's curvature; along y it can be
// coarser. See docs/model.md ("Mesh") for the chord error this controls.
struct MeshSpacing {
  double along_x_m = 0.008;
  double along_y_m = 0.022;
  // Above 0: a pattern's triangles at this edge length, whatever its file's own Mesh edge
  // length (the coarse copy of a garment that a dressing starts from; docs/dressing.md).
  double pattern_edge_length_m = 0.0;
  void validate() const;  // throws std::invalid_argument unless both are positive
};

// A width x height rectangle, lower-left corner at the origin, meshed as a grid of
// round(width / along_x_m) x round(height / along_y_m) cells, each cut by its diagonal from
// lower right to upper left. Every triangle is right-angled, so the triangulation is
// Delaunay; every vertex has the same neighbourhood, and two panels sewn side by side
// continue the same pattern across the seam, so a uniform state gives a uniform pressure at
// every vertex, seams included (an offset-row mesh, with half cells at the side edges, does
// not: its seam vertices read several percent off the mean).
// Edges: "bottom" and "top" (left to right), "left" and "right" (bottom to top).
Panel make_rectangle_panel(const std::string& name, double width_m, double height_m,
                           const MeshSpacing& spacing);

}  // namespace tightfit
