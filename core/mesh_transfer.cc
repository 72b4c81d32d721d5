#include "core/mesh_transfer.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace tightfit {

namespace {

// Barycentric coordinates of q in the triangle (a, b, c) of the plane, unclamped.
Vec3 barycentric_2d(const Vec2& q, const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 e0 = b - a, e1 = c - a, d = q - a;
  const double det = e0.x() * e1.y() - e0.y() * e1.x();
  const double v = (d.x() * e1.y() - d.y() * e1.x()) / det;
  const double w = (e0.x() * d.y() - e0.y() * d.x()) / det;
  return Vec3(1.0 - v - w, v, w);
}

// Distance from q to the segment (a, b) of the plane.
double to_segment(const Vec2& q, const Vec2& a, const Vec2& b) {
  const double t = std::clamp((q - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (q - (a + t * (b - a))).norm();
}

// Distance from q to the triangle: zero inside, else to its nearest side.
double to_triangle(const Vec2& q, const std::array<Vec2, 3>& corners, const Vec3& b) {
  if (b.minCoeff() >= 0.0) return 0.0;
  return std::min({to_segment(q, corners[0], corners[1]), to_segment(q, corners[1], corners[2]),
                   to_segment(q, corners[2], corners[0])});
}

int panel_count(const SimulationMesh& mesh) {
  return int(mesh.panel_vertex_offset.size());
}

}  // namespace

std::vector<Vec3> transfer_positions(const SimulationMesh& coarse,
                                     const std::vector<Vec3>& coarse_m,
                                     const SimulationMesh& fine) {
  if (panel_count(coarse) != panel_count(fine))
    throw std::invalid_argument("mesh transfer: the coarse mesh has " +
                                std::to_string(panel_count(coarse)) + " panels, the fine one " +
                                std::to_string(panel_count(fine)));
  if (static_cast<int>(coarse_m.size()) != coarse.n_vertices)
    throw std::invalid_argument("mesh transfer: " + std::to_string(coarse_m.size()) +
                                " positions for a coarse mesh of " +
                                std::to_string(coarse.n_vertices) + " vertices");
  std::vector<std::vector<int>> coarse_of_panel(panel_count(coarse));
  for (std::size_t t = 0; t < coarse.triangles.size(); ++t)
    coarse_of_panel[coarse.triangle_panel[t]].push_back(int(t));

  // The position of a panel copy: rest point q of panel p in the coarse panel.
  const auto carried = [&](int p, const Vec2& q) {
    if (coarse_of_panel[p].empty())
      throw std::invalid_argument("mesh transfer: panel " + std::to_string(p) +
                                  " has no triangle in the coarse mesh");
    double nearest = std::numeric_limits<double>::infinity();
    Vec3 best_b = Vec3::Zero();
    int best = -1;
    for (const int t : coarse_of_panel[p]) {
      const auto& r = coarse.rest_triangles[t];
      const Vec3 b = barycentric_2d(q, r[0], r[1], r[2]);
      const double d = to_triangle(q, r, b);
      if (d < nearest) nearest = d, best_b = b, best = t;
      if (d == 0.0) break;
    }
    const Triangle& corners = coarse.triangles[best];
    return Vec3(best_b[0] * coarse_m[corners[0]] + best_b[1] * coarse_m[corners[1]] +
                best_b[2] * coarse_m[corners[2]]);
  };

  // Each welded fine vertex: the mean over the panels it lies on of its copy's position.
  std::vector<Vec3> sum(fine.n_vertices, Vec3::Zero());
  std::vector<std::vector<int>> panels_seen(fine.n_vertices);
  for (std::size_t t = 0; t < fine.triangles.size(); ++t) {
    const int p = fine.triangle_panel[t];
    for (int k = 0; k < 3; ++k) {
      const int w = fine.triangles[t][k];
      auto& seen = panels_seen[w];
      if (std::find(seen.begin(), seen.end(), p) != seen.end()) continue;
      seen.push_back(p);
      sum[w] += carried(p, fine.rest_triangles[t][k]);
    }
  }
  for (int w = 0; w < fine.n_vertices; ++w)
    if (!panels_seen[w].empty()) sum[w] /= double(panels_seen[w].size());
  return sum;
}

}  // namespace tightfit
