#include "massspring/lumped_mass.h"

#include <algorithm>
#include <map>
#include <utility>

namespace tightfit {

std::vector<double> rest_vertex_areas_m2(const SimulationMesh& mesh) {
  std::vector<double> areas(mesh.n_vertices, 0.0);
  const std::vector<double> triangle_area = rest_triangle_areas(mesh);
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
    for (int v : mesh.triangles[k]) areas[v] += triangle_area[k] / 3.0;
  return areas;
}

std::vector<double> lumped_masses_kg(const SimulationMesh& mesh, double areal_density_kg_per_m2) {
  std::vector<double> masses = rest_vertex_areas_m2(mesh);
  for (double& m : masses) m *= areal_density_kg_per_m2;
  return masses;
}

double mean_rest_edge_length_m(const SimulationMesh& mesh) {
  // An edge shared by two triangles has the same rest length in both (a seam joins edges of
  // equal length), so the first triangle met gives it.
  std::map<std::pair<int, int>, double> length;
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const auto key = std::minmax(mesh.triangles[k][i], mesh.triangles[k][j]);
      length.emplace(key, (mesh.rest_triangles[k][j] - mesh.rest_triangles[k][i]).norm());
    }
  if (length.empty()) return 0.0;
  double sum = 0.0;
  for (const auto& entry : length) sum += entry.second;
  return sum / static_cast<double>(length.size());
}

}  // namespace tightfit
