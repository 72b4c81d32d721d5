#include "massspring/unwelded_panels.h"

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace tightfit {

namespace {

// Copies of each welded vertex within one panel: usually one, two where a panel is sewn to
// itself (a one-panel tube).
using PanelCopies = std::multimap<int, int>;

// The panel vertices of triangle k: among the copies of its welded corners, the choice whose
// layout edges have the rest edges' lengths (layout = rest coordinates + the panel's offset,
// turned by the grain angle, so lengths agree; a copy across a self-seam is a panel width off).
Triangle panel_corners(const SimulationMesh& welded, const PanelCopies& copies, std::size_t k) {
  std::array<std::vector<int>, 3> candidates;
  for (int i = 0; i < 3; ++i) {
    const auto range = copies.equal_range(welded.triangles[k][i]);
    for (auto it = range.first; it != range.second; ++it) candidates[i].push_back(it->second);
    if (candidates[i].empty())
      throw std::invalid_argument("mass spring: triangle " + std::to_string(k) +
                                  " has a corner outside its panel");
  }
  const auto& rest = welded.rest_triangles[k];
  Triangle best{};
  double best_mismatch = std::numeric_limits<double>::infinity();
  for (int a : candidates[0])
    for (int b : candidates[1])
      for (int c : candidates[2]) {
        const Triangle t{a, b, c};
        double mismatch = 0.0;
        for (int i = 0; i < 3; ++i) {
          const int j = (i + 1) % 3;
          const double layout =
              (welded.layout_positions_m[t[j]] - welded.layout_positions_m[t[i]]).norm();
          mismatch += std::abs(layout - (rest[j] - rest[i]).norm());
        }
        if (mismatch < best_mismatch) {
          best_mismatch = mismatch;
          best = t;
        }
      }
  const double size = (rest[1] - rest[0]).norm() + (rest[2] - rest[1]).norm();
  if (!(best_mismatch <= 1e-6 * size))
    throw std::invalid_argument("mass spring: triangle " + std::to_string(k) +
                                " does not match its panel's layout");
  return best;
}

}  // namespace

UnweldedPanels unweld(const SimulationMesh& welded) {
  const int n = welded.n_unwelded_vertices();
  const int n_panels = static_cast<int>(welded.panel_vertex_offset.size());
  std::vector<PanelCopies> copies(n_panels);
  for (int p = 0; p < n_panels; ++p) {
    const int end = p + 1 < n_panels ? welded.panel_vertex_offset[p + 1] : n;
    for (int u = welded.panel_vertex_offset[p]; u < end; ++u)
      copies[p].emplace(welded.welded_index[u], u);
  }

  UnweldedPanels out;
  SimulationMesh& mesh = out.mesh;
  mesh.n_vertices = n;
  mesh.rest_triangles = welded.rest_triangles;
  mesh.triangle_panel = welded.triangle_panel;
  mesh.panel_vertex_offset = welded.panel_vertex_offset;
  mesh.layout_positions_m = welded.layout_positions_m;
  mesh.welded_index.resize(n);
  for (int u = 0; u < n; ++u) mesh.welded_index[u] = u;
  mesh.triangles.reserve(welded.triangles.size());
  for (std::size_t k = 0; k < welded.triangles.size(); ++k)
    mesh.triangles.push_back(panel_corners(welded, copies.at(welded.triangle_panel[k]), k));

  std::vector<std::vector<int>> copies_of(welded.n_vertices);
  for (int u = 0; u < n; ++u) copies_of[welded.welded_index[u]].push_back(u);
  for (const auto& group : copies_of)
    for (std::size_t i = 0; i < group.size(); ++i)
      for (std::size_t j = i + 1; j < group.size(); ++j)
        out.seam_pairs.emplace_back(group[i], group[j]);
  return out;
}

std::vector<Vec3> weld_positions(const SimulationMesh& welded,
                                 const std::vector<Vec3>& unwelded_positions_m) {
  std::vector<Vec3> x(welded.n_vertices, Vec3::Zero());
  std::vector<int> count(welded.n_vertices, 0);
  for (int u = 0; u < welded.n_unwelded_vertices(); ++u) {
    x[welded.welded_index[u]] += unwelded_positions_m[u];
    ++count[welded.welded_index[u]];
  }
  for (int v = 0; v < welded.n_vertices; ++v)
    if (count[v] > 0) x[v] /= count[v];
  return x;
}

}  // namespace tightfit
