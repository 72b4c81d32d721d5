#include "core/garment.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace tightfit {

namespace {

// Union-find over panel vertices: a seam makes two vertices one.
class VertexUnion {
 public:
  explicit VertexUnion(int n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int root(int v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  void join(int a, int b) {
    a = root(a);
    b = root(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

const std::vector<int>& seam_edge(const Garment& garment, int panel, const std::string& edge) {
  if (panel < 0 || panel >= static_cast<int>(garment.panels.size()))
    throw std::invalid_argument("garment '" + garment.name + "': seam names panel " +
                                std::to_string(panel) + ", which does not exist");
  const auto& edges = garment.panels[panel].edges;
  const auto found = edges.find(edge);
  if (found == edges.end())
    throw std::invalid_argument("garment '" + garment.name + "': panel '" +
                                garment.panels[panel].name + "' has no edge '" + edge + "'");
  return found->second;
}

}  // namespace

SimulationMesh weld(const Garment& garment) {
  SimulationMesh mesh;
  int n_unwelded = 0;
  for (const Panel& panel : garment.panels) {
    mesh.panel_vertex_offset.push_back(n_unwelded);
    for (const Vec2& x : panel.rest_positions_m)
      mesh.layout_positions_m.push_back(x + panel.layout_offset_m);
    n_unwelded += static_cast<int>(panel.rest_positions_m.size());
  }

  VertexUnion sewn(n_unwelded);
  for (const Seam& seam : garment.seams) {
    const auto& a = seam_edge(garment, seam.panel_a, seam.edge_a);
    const auto& b = seam_edge(garment, seam.panel_b, seam.edge_b);
    if (a.size() != b.size())
      throw std::invalid_argument("garment '" + garment.name + "': seam " + seam.edge_a + " - " +
                                  seam.edge_b + " joins edges of " + std::to_string(a.size()) +
                                  " and " + std::to_string(b.size()) + " vertices");
    for (std::size_t i = 0; i < a.size(); ++i)
      sewn.join(mesh.panel_vertex_offset[seam.panel_a] + a[i],
                mesh.panel_vertex_offset[seam.panel_b] + b[seam.reversed ? b.size() - 1 - i : i]);
  }

  // Number the welded vertices in the order their first panel vertex appears.
  mesh.welded_index.assign(n_unwelded, -1);
  std::vector<int> number_of_root(n_unwelded, -1);
  for (int v = 0; v < n_unwelded; ++v) {
    const int r = sewn.root(v);
    if (number_of_root[r] < 0) number_of_root[r] = mesh.n_vertices++;
    mesh.welded_index[v] = number_of_root[r];
  }

  for (std::size_t p = 0; p < garment.panels.size(); ++p) {
    const Panel& panel = garment.panels[p];
    const int offset = mesh.panel_vertex_offset[p];
    // Rotate pattern coordinates into grain axes: X_grain = R(-grain angle) X.
    const Eigen::Rotation2Dd to_grain(-panel.grain_angle_rad);
    for (const Triangle& t : panel.triangles) {
      mesh.triangles.push_back({mesh.welded_index[offset + t[0]], mesh.welded_index[offset + t[1]],
                                mesh.welded_index[offset + t[2]]});
      mesh.rest_triangles.push_back({to_grain * panel.rest_positions_m[t[0]],
                                     to_grain * panel.rest_positions_m[t[1]],
                                     to_grain * panel.rest_positions_m[t[2]]});
      mesh.triangle_panel.push_back(static_cast<int>(p));
    }
    for (const auto& [edge_name, vertices] : panel.edges) {
      auto& group = mesh.vertex_groups[edge_name];
      for (int v : vertices) group.push_back(mesh.welded_index[offset + v]);
    }
  }
  for (auto& [name, group] : mesh.vertex_groups) {
    std::sort(group.begin(), group.end());
    group.erase(std::unique(group.begin(), group.end()), group.end());
  }
  return mesh;
}

double rest_triangle_area(const std::array<Vec2, 3>& rest_m) {
  const Vec2 e1 = rest_m[1] - rest_m[0], e2 = rest_m[2] - rest_m[0];
  return 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
}

std::vector<double> rest_triangle_areas(const SimulationMesh& mesh) {
  std::vector<double> areas;
  areas.reserve(mesh.rest_triangles.size());
  for (const auto& r : mesh.rest_triangles) areas.push_back(rest_triangle_area(r));
  return areas;
}

double rest_area(const SimulationMesh& mesh) {
  const auto areas = rest_triangle_areas(mesh);
  return std::accumulate(areas.begin(), areas.end(), 0.0);
}

std::vector<double> rest_vertex_areas_m2(const SimulationMesh& mesh) {
  std::vector<double> areas(mesh.n_vertices, 0.0);
  const std::vector<double> triangle_area = rest_triangle_areas(mesh);
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
    for (int v : mesh.triangles[k]) areas[v] += triangle_area[k] / 3.0;
  return areas;
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
