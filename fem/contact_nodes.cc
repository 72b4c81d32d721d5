#include "fem/contact_nodes.h"

#include "core/mesh_geometry.h"

#include <algorithm>

namespace tightfit {

std::vector<double> node_edge_lengths_m(const SimulationMesh& mesh,
                                        const std::vector<std::array<int, 2>>& edge_ends,
                                        int element_degree) {
  const int n = mesh.n_vertices;
  std::vector<double> sum(n, 0.0);
  std::vector<int> count(n, 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& v = mesh.triangles[t];
    const auto& r = mesh.rest_triangles[t];
    for (int k = 0; k < 3; ++k) {
      const double length = (r[(k + 1) % 3] - r[k]).norm();  // edge k -> k+1
      for (int end : {v[k], v[(k + 1) % 3]}) {
        sum[end] += length;
        ++count[end];
      }
    }
  }
  std::vector<double> h(n, 0.0);
  for (int w = 0; w < n; ++w) h[w] = count[w] > 0 ? sum[w] / count[w] : 0.0;
  if (element_degree == 2)
    for (const auto& ends : edge_ends) h.push_back(0.5 * (h[ends[0]] + h[ends[1]]));
  return h;
}

std::vector<double> nodal_rest_areas_m2(const SimulationMesh& mesh,
                                        const std::map<std::array<int, 2>, int>& edge_index,
                                        int element_degree) {
  const bool quadratic = element_degree == 2;
  const std::vector<double> areas = rest_triangle_areas(mesh);
  std::vector<double> area(mesh.n_vertices + edge_index.size(), 0.0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& v = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      area[v[k]] += areas[t] / (quadratic ? 12.0 : 3.0);
      if (!quadratic) continue;
      std::array<int, 2> ends{v[k], v[(k + 1) % 3]};
      std::sort(ends.begin(), ends.end());
      area[mesh.n_vertices + edge_index.at(ends)] += areas[t] / 4.0;
    }
  }
  return area;
}

std::vector<double> nodal_penalties_N_per_m(const std::vector<double>& node_rest_area_m2,
                                            double beta_Y_N_per_m,
                                            const std::vector<double>& node_edge_m) {
  std::vector<double> penalty(node_rest_area_m2.size(), 0.0);
  for (std::size_t k = 0; k < penalty.size(); ++k)
    penalty[k] = beta_Y_N_per_m * node_rest_area_m2[k] / (node_edge_m[k] * node_edge_m[k]);
  return penalty;
}

}  // namespace tightfit
