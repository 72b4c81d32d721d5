// Geometry of a deformed triangle mesh: areas, normals, stretches.
#pragma once

#include "core/garment.h"
#include "core/types.h"

#include <vector>

namespace tightfit {

// Current area of every triangle, m^2.
std::vector<double> triangle_areas(const std::vector<Triangle>& triangles,
                                   const std::vector<Vec3>& positions_m);

// How the area round a vertex is counted.
enum class VertexAreaDefinition {
  // A third of each adjacent triangle: the areas sum to the mesh area, so pressure times area
  // balances force (the default).
  barycentric,
  // The whole of each adjacent triangle, as the paper's Section 2.2 defines it: the areas sum
  // to three times the mesh area, so the pressure reads a third (docs/model.md, "The pressure
  // extractor").
  adjacent_triangles,
  // The mixed Voronoi area (Meyer, Desbrun, Schroeder and Barr, "Discrete differential-geometry
  // operators for triangulated 2-manifolds", 2003, Fig. 4): the part of each adjacent triangle
  // nearer to the vertex than to the other corners (a half or a quarter of an obtuse
  // triangle). Sums to the mesh area like the barycentric area, but follows the vertex's true
  // share where the mesh spacing changes (a row that closes with a half-spacing vertex).
  mixed_voronoi,
};
const char* to_string(VertexAreaDefinition definition);

std::vector<double> vertex_areas(const std::vector<Triangle>& triangles,
                                 const std::vector<Vec3>& positions_m, int n_vertices,
                                 VertexAreaDefinition definition);

// Unit vertex normals, the area-weighted mean of the adjacent triangles' normals (their
// orientation follows the triangles' winding).
std::vector<Vec3> vertex_normals(const std::vector<Triangle>& triangles,
                                 const std::vector<Vec3>& positions_m, int n_vertices);

// Deformation gradient F = dx/dX (3x2) of one linear triangle from its rest corners (grain
// axes) and current corners.
Mat32 deformation_gradient(const std::array<Vec2, 3>& rest, const Vec3& x0, const Vec3& x1,
                           const Vec3& x2);

// Principal stretches (largest, smallest) at each vertex.
using PrincipalStretches = std::vector<std::array<double, 2>>;

// The eigenvalues of sqrt(C) of the adjacent triangles, averaged with their rest areas as
// weights.
PrincipalStretches vertex_principal_stretches(const SimulationMesh& mesh,
                                              const std::vector<Vec3>& positions_m);

}  // namespace tightfit
