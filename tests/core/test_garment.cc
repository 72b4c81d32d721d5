// Garments in pattern space: panel meshes, seams, welded meshes.
#include "core/garment.h"
#include "core/mesh_geometry.h"
#include "core/tube_garment.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace tightfit {
namespace {

TEST(RectanglePanel, TrianglesTileTheRectangleCounterClockwise) {
  const Panel panel = make_rectangle_panel("p", 0.1878, 0.24, MeshSpacing{});
  double area = 0.0;
  for (const Triangle& t : panel.triangles) {
    const Vec2 e1 = panel.rest_positions_m[t[1]] - panel.rest_positions_m[t[0]];
    const Vec2 e2 = panel.rest_positions_m[t[2]] - panel.rest_positions_m[t[0]];
    const double doubled = e1.x() * e2.y() - e1.y() * e2.x();
    EXPECT_GT(doubled, 0.0);
    area += 0.5 * doubled;
  }
  EXPECT_NEAR(area, 0.1878 * 0.24, 1e-12);
}

// The grid's cells are cut by one diagonal: every triangle has one right corner and two acute
// ones, and the mesh is Delaunay: the two corners facing an interior edge sum to at most pi
// (exactly pi across each diagonal, whose four points lie on one circle).
TEST(RectanglePanel, EveryTriangleIsRightAngledAndTheMeshIsDelaunay) {
  const Panel panel = make_rectangle_panel("p", 0.157, 0.24, MeshSpacing{});
  const auto& x = panel.rest_positions_m;
  std::map<std::pair<int, int>, std::vector<double>> facing_angles;  // edge -> opposite corners
  for (const Triangle& t : panel.triangles) {
    int right = 0, acute = 0;
    for (int i = 0; i < 3; ++i) {
      const int j = t[(i + 1) % 3], k = t[(i + 2) % 3];
      const Vec2 a = x[j] - x[t[i]], b = x[k] - x[t[i]];
      const double cosine = a.dot(b) / (a.norm() * b.norm());
      if (std::abs(cosine) < 1e-12) ++right;
      if (cosine >= 1e-12) ++acute;
      facing_angles[std::minmax(j, k)].push_back(std::acos(std::clamp(cosine, -1.0, 1.0)));
    }
    EXPECT_EQ(right, 1);
    EXPECT_EQ(acute, 2);
  }
  int interior = 0;
  for (const auto& [edge, angles] : facing_angles) {
    ASSERT_LE(angles.size(), 2u);
    if (angles.size() < 2) continue;
    ++interior;
    EXPECT_LE(angles[0] + angles[1], M_PI + 1e-12) << edge.first << "-" << edge.second;
  }
  EXPECT_GT(interior, 0);
}

TEST(TubeGarment, WeldingClosesTheTubeIntoAnAnnulus) {
  const Garment g = make_tube_garment("4 5T", 0.1878, 0.24, 2, MeshSpacing{});
  const SimulationMesh mesh = weld(g);
  // An annulus has Euler characteristic V - E + F = 0.
  std::set<std::pair<int, int>> edges;
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) edges.insert(std::minmax(t[i], t[(i + 1) % 3]));
  EXPECT_EQ(mesh.n_vertices - int(edges.size()) + int(mesh.triangles.size()), 0);
  EXPECT_NEAR(rest_area(mesh), 2 * 0.1878 * 0.24, 1e-12);
  EXPECT_EQ(mesh.n_unwelded_vertices() - mesh.n_vertices,
            2 * int(g.panels[0].edges.at("left").size()));
}

TEST(TubeGarment, DefaultSpacingGivesThePapersVertexCounts) {
  // The paper's Table 3: 575 vertices for "4 5T" and 485 for "T": no finer than those.
  const SimulationMesh large = weld(make_tube_garment("4 5T", 0.1878, 0.24, 2, MeshSpacing{}));
  const SimulationMesh small = weld(make_tube_garment("T", 0.157, 0.24, 2, MeshSpacing{}));
  EXPECT_LE(large.n_vertices, 575);
  EXPECT_GE(large.n_vertices, 0.9 * 575);
  EXPECT_LE(small.n_vertices, 485);
  EXPECT_GE(small.n_vertices, 0.9 * 485);
}

TEST(TubeGarment, GrainAngleRotatesTheRestTriangles) {
  Garment g = make_tube_garment("t", 0.1, 0.1, 1, MeshSpacing{0.02, 0.02});
  g.panels[0].grain_angle_rad = M_PI / 2;
  const SimulationMesh mesh = weld(g);
  const Panel& p = g.panels[0];
  const Vec2 pattern =
      p.rest_positions_m[p.triangles[0][1]] - p.rest_positions_m[p.triangles[0][0]];
  const Vec2 grain = mesh.rest_triangles[0][1] - mesh.rest_triangles[0][0];
  // The weft now runs along the pattern's y: grain x = pattern y, grain y = -pattern x.
  EXPECT_NEAR(grain.x(), pattern.y(), 1e-15);
  EXPECT_NEAR(grain.y(), -pattern.x(), 1e-15);
}

}  // namespace
}  // namespace tightfit
