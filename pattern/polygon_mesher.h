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

// `outline_m`: a simple polygon, counter-clockwise, its last point not repeating the first.
// Triangles are refined until every edge is at most `edge_length_m` and every angle at least
// `min_angle_deg` (CGAL guarantees termination up to about 20.7 degrees and usually reaches
// 30). Throws std::invalid_argument for a bad polygon or bound.
PolygonMesh mesh_polygon(const std::vector<Vec2>& outline_m, double edge_length_m,
                         double min_angle_deg);

// Element quality of a triangle mesh: the smallest angle and the spread of edge lengths.
struct MeshQuality {
  double min_angle_deg = 0.0;
  double min_edge_m = 0.0, mean_edge_m = 0.0, max_edge_m = 0.0;
};
MeshQuality mesh_quality(const std::vector<Vec2>& points_m, const std::vector<Triangle>& triangles);

}  // namespace tightfit::pattern
