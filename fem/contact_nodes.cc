#include "fem/contact_nodes.h"

#include "core/mesh_geometry.h"

#include <algorithm>

namespace tightfit {

void add_node_edge_lengths(const Triangle& v, const std::array<Vec2, 3>& rest_m,
                           std::vector<double>& length_sum_m, std::vector<double>& count) {
  for (int k = 0; k < 3; ++k) {
    const double length = (rest_m[(k + 1) % 3] - rest_m[k]).norm();  // edge k -> k+1
    for (int end : {v[k], v[(k + 1) % 3]}) {
      length_sum_m[end] += length;
      count[end] += 1.0;
    }
  }
}

std::vector<double> node_edge_lengths_m(const std::vector<double>& length_sum_m,
                                        const std::vector<double>& count,
                                        const std::vector<std::array<int, 2>>& edge_ends,
                                        int element_degree) {
  std::vector<double> h(length_sum_m.size(), 0.0);
  for (std::size_t w = 0; w < h.size(); ++w)
    h[w] = count[w] > 0.0 ? length_sum_m[w] / count[w] : 0.0;
  if (element_degree == 2)
    for (const auto& ends : edge_ends) h.push_back(0.5 * (h[ends[0]] + h[ends[1]]));
  return h;
}

std::vector<double> node_edge_lengths_m(const SimulationMesh& mesh,
                                        const std::vector<std::array<int, 2>>& edge_ends,
                                        int element_degree) {
  std::vector<double> sum(mesh.n_vertices, 0.0), count(mesh.n_vertices, 0.0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    add_node_edge_lengths(mesh.triangles[t], mesh.rest_triangles[t], sum, count);
  return node_edge_lengths_m(sum, count, edge_ends, element_degree);
}

void add_nodal_rest_areas(const Triangle& v, double area_m2, int n_vertices,
                          const std::map<std::array<int, 2>, int>& edge_index, int element_degree,
                          std::vector<double>& area_m2_of_node) {
  const bool quadratic = element_degree == 2;
  for (int k = 0; k < 3; ++k) {
    area_m2_of_node[v[k]] += area_m2 / (quadratic ? 12.0 : 3.0);
    if (!quadratic) continue;
    std::array<int, 2> ends{v[k], v[(k + 1) % 3]};
    std::sort(ends.begin(), ends.end());
    area_m2_of_node[n_vertices + edge_index.at(ends)] += area_m2 / 4.0;
  }
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
