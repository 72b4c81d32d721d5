// Triangulates one panel's outline (a closed polygon) with CGAL's 2D constrained Delaunay
// mesher: triangles no longer than a target edge length and no angle below a bound.
#pragma once

#include "core/types.h"

#include <vector>

namespace tightfit::pattern {

struct PolygonMesh {
  // The outline's points first, in order, then the points the mesher added.
  std::vector<Vec2> points_m;
  std::vector<Triangle> triangles;  // counter-clockwise
  // Points the mesher added on the outline: which chord (from outline point k to k + 1) and
  // where along it (0 to 1). A conforming seam needs the same point on the other side.
  struct BoundaryPoint {
    int chord = 0;
    double along = 0.0;
  };
  std::vector<BoundaryPoint> added_on_outline;
};

// The most vertices a mesh of outline `outline_m` at edge length `edge_length_m` may take:
// ten times the estimate for equilateral triangles of that side, 2 A / (sqrt(3) h^2) inside
// plus L / h on the outline (and every outline point), and 1000 more. A spike or a neck far
// narrower than the edge length would make the angle bound refine towards it without end.
double mesh_vertex_budget(const std::vector<Vec2>& outline_m, double edge_length_m);

// `outline_m`: a simple polygon, counter-clockwise, its last point not repeating the first.
// Triangles are refined until every edge is at most `edge_length_m` and every angle at least
// `min_angle_deg` (CGAL guarantees termination up to about 20.7 degrees and usually reaches
// 30). Throws std::invalid_argument for a bad polygon or bound: an outline that crosses itself,
// turns back along itself or has a corner under a degree (a spike or a slit), or a mesh of more
// than `max_vertices` (0: mesh_vertex_budget of this outline).
PolygonMesh mesh_polygon(const std::vector<Vec2>& outline_m, double edge_length_m,
                         double min_angle_deg, double max_vertices = 0);

// Element quality of a triangle mesh: the smallest angle and the spread of edge lengths.
struct MeshQuality {
  double min_angle_deg = 0.0;
  double min_edge_m = 0.0, mean_edge_m = 0.0, max_edge_m = 0.0;
};
MeshQuality mesh_quality(const std::vector<Vec2>& points_m, const std::vector<Triangle>& triangles);

}  // namespace tightfit::pattern
