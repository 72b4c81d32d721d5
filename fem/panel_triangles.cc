#include "fem/panel_triangles.h"

#include <limits>
#include <map>

namespace tightfit {

std::vector<Triangle> unwelded_triangles(const SimulationMesh& mesh) {
  const int n_unwelded = mesh.n_unwelded_vertices();
  std::vector<std::multimap<int, int>> copies(mesh.panel_vertex_offset.size());
  for (std::size_t p = 0; p < mesh.panel_vertex_offset.size(); ++p) {
    const int end =
        p + 1 < mesh.panel_vertex_offset.size() ? mesh.panel_vertex_offset[p + 1] : n_unwelded;
    for (int u = mesh.panel_vertex_offset[p]; u < end; ++u)
      copies[p].emplace(mesh.welded_index[u], u);
  }
  std::vector<Triangle> result;
  result.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& panel_copies = copies[mesh.triangle_panel[t]];
    std::array<std::vector<int>, 3> candidates;
    for (int k = 0; k < 3; ++k) {
      const auto range = panel_copies.equal_range(mesh.triangles[t][k]);
      for (auto it = range.first; it != range.second; ++it) candidates[k].push_back(it->second);
    }
    const auto& rest = mesh.rest_triangles[t];
    double best_mismatch = std::numeric_limits<double>::infinity();
    Triangle best{};
    for (int a : candidates[0])
      for (int b : candidates[1])
        for (int c : candidates[2]) {
          const std::array<int, 3> u{a, b, c};
          double mismatch = 0.0;
          for (int k = 0; k < 3; ++k) {
            const int l = (k + 1) % 3;
            const double layout =
                (mesh.layout_positions_m[u[l]] - mesh.layout_positions_m[u[k]]).norm();
            const double grain = (rest[l] - rest[k]).norm();
            mismatch += (layout - grain) * (layout - grain);
          }
          if (mismatch < best_mismatch) {
            best_mismatch = mismatch;
            best = {a, b, c};
          }
        }
    result.push_back(best);
  }
  return result;
}

}  // namespace tightfit
