#include "fem/contact_nodes.h"

#include "core/mesh_geometry.h"

#include <algorithm>

namespace tightfit {

std::vector<double> nodal_penalties_N_per_m(const SimulationMesh& mesh,
                                            const std::map<std::array<int, 2>, int>& edge_index,
                                            int element_degree, double k_Pa_per_m) {
  const bool quadratic = element_degree == 2;
  const std::vector<double> areas = rest_triangle_areas(mesh);
  std::vector<double> penalty(mesh.n_vertices + edge_index.size(), 0.0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& v = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      penalty[v[k]] += k_Pa_per_m * areas[t] / (quadratic ? 12.0 : 3.0);
      if (!quadratic) continue;
      std::array<int, 2> ends{v[k], v[(k + 1) % 3]};
      std::sort(ends.begin(), ends.end());
      penalty[mesh.n_vertices + edge_index.at(ends)] += k_Pa_per_m * areas[t] / 4.0;
    }
  }
  return penalty;
}

}  // namespace tightfit
