#include "core/mesh_geometry.h"

#include <Eigen/Dense>

#include <cmath>

namespace tightfit {

namespace {
// Twice the area vector of a triangle (cross product of two edges).
Vec3 doubled_area_vector(const Triangle& t, const std::vector<Vec3>& x) {
  return (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);
}
}  // namespace

std::vector<double> triangle_areas(const std::vector<Triangle>& triangles,
                                   const std::vector<Vec3>& positions_m) {
  std::vector<double> areas;
  areas.reserve(triangles.size());
  for (const Triangle& t : triangles)
    areas.push_back(0.5 * doubled_area_vector(t, positions_m).norm());
  return areas;
}

const char* to_string(VertexAreaDefinition definition) {
  switch (definition) {
    case VertexAreaDefinition::barycentric:
      return "barycentric";
    case VertexAreaDefinition::adjacent_triangles:
      return "adjacent triangles";
    case VertexAreaDefinition::mixed_voronoi:
      return "mixed voronoi";
  }
  return "unknown";
}

namespace {
// Meyer et al. 2003, Fig. 4: each corner's Voronoi share of one triangle, or A/2 for the obtuse
// corner and A/4 for the others when the triangle is obtuse.
void add_mixed_voronoi_areas(const Vec3& x0, const Vec3& x1, const Vec3& x2, double area,
                             double& a0, double& a1, double& a2) {
  const Vec3 e0 = x2 - x1, e1 = x0 - x2, e2 = x1 - x0;                // edge opposite each corner
  const double d0 = -e1.dot(e2), d1 = -e2.dot(e0), d2 = -e0.dot(e1);  // |.|^2 cos(corner)
  if (d0 < 0 || d1 < 0 || d2 < 0) {
    a0 += area * (d0 < 0 ? 0.5 : 0.25);
    a1 += area * (d1 < 0 ? 0.5 : 0.25);
    a2 += area * (d2 < 0 ? 0.5 : 0.25);
    return;
  }
  // cot(corner) = cos / sin = d / (2 area); corner i gets (|e_j|^2 cot_j + |e_k|^2 cot_k) / 8.
  const double c0 = d0 / (2 * area), c1 = d1 / (2 * area), c2 = d2 / (2 * area);
  a0 += (e1.squaredNorm() * c1 + e2.squaredNorm() * c2) / 8.0;
  a1 += (e2.squaredNorm() * c2 + e0.squaredNorm() * c0) / 8.0;
  a2 += (e0.squaredNorm() * c0 + e1.squaredNorm() * c1) / 8.0;
}
}  // namespace

std::vector<double> vertex_areas(const std::vector<Triangle>& triangles,
                                 const std::vector<Vec3>& positions_m, int n_vertices,
                                 VertexAreaDefinition definition) {
  std::vector<double> areas(n_vertices, 0.0);
  const auto triangle_area = triangle_areas(triangles, positions_m);
  if (definition == VertexAreaDefinition::mixed_voronoi) {
    for (std::size_t k = 0; k < triangles.size(); ++k) {
      const Triangle& t = triangles[k];
      if (triangle_area[k] > 0)
        add_mixed_voronoi_areas(positions_m[t[0]], positions_m[t[1]], positions_m[t[2]],
                                triangle_area[k], areas[t[0]], areas[t[1]], areas[t[2]]);
    }
    return areas;
  }
  const double share = definition == VertexAreaDefinition::barycentric ? 1.0 / 3.0 : 1.0;
  for (std::size_t k = 0; k < triangles.size(); ++k)
    for (int v : triangles[k]) areas[v] += share * triangle_area[k];
  return areas;
}

std::vector<Vec3> vertex_normals(const std::vector<Triangle>& triangles,
                                 const std::vector<Vec3>& positions_m, int n_vertices) {
  std::vector<Vec3> normals(n_vertices, Vec3::Zero());
  for (const Triangle& t : triangles) {
    const Vec3 n = doubled_area_vector(t, positions_m);  // length = 2 area: area weighting
    for (int v : t) normals[v] += n;
  }
  for (Vec3& n : normals) {
    const double length = n.norm();
    if (length > 0) n /= length;
  }
  return normals;
}

Mat32 deformation_gradient(const std::array<Vec2, 3>& rest, const Vec3& x0, const Vec3& x1,
                           const Vec3& x2) {
  Mat2 dX;
  dX.col(0) = rest[1] - rest[0];
  dX.col(1) = rest[2] - rest[0];
  Mat32 dx;
  dx.col(0) = x1 - x0;
  dx.col(1) = x2 - x0;
  return dx * dX.inverse();
}

PrincipalStretches vertex_principal_stretches(const SimulationMesh& mesh,
                                              const std::vector<Vec3>& x) {
  std::vector<std::array<double, 2>> stretches(mesh.n_vertices, {0.0, 0.0});
  std::vector<double> weight(mesh.n_vertices, 0.0);
  const auto rest_area = rest_triangle_areas(mesh);
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
    const Triangle& t = mesh.triangles[k];
    const Mat32 F = deformation_gradient(mesh.rest_triangles[k], x[t[0]], x[t[1]], x[t[2]]);
    const Eigen::SelfAdjointEigenSolver<Mat2> eigen(F.transpose() * F, Eigen::EigenvaluesOnly);
    const double largest = std::sqrt(std::max(0.0, eigen.eigenvalues()(1)));
    const double smallest = std::sqrt(std::max(0.0, eigen.eigenvalues()(0)));
    for (int v : t) {
      stretches[v][0] += rest_area[k] * largest;
      stretches[v][1] += rest_area[k] * smallest;
      weight[v] += rest_area[k];
    }
  }
  for (int v = 0; v < mesh.n_vertices; ++v)
    if (weight[v] > 0)
      for (double& s : stretches[v]) s /= weight[v];
  return stretches;
}

}  // namespace tightfit
