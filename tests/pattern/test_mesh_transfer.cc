// A state carried from a coarse mesh of a pattern to a finer one (core/mesh_transfer.h): a
// position field linear in the rest (pattern) coordinates arrives exactly at every fine vertex,
// inside the coarse outline and where the fine outline bulges past its chords; on the sewn top
// a field that is one rigid placement of the flat layout of both panels stays one.
#include "core/mesh_transfer.h"
#include "pattern/pattern_garment.h"
#include "tests/pattern/aaron_bodice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace tightfit::pattern {
namespace {

SimulationMesh meshed(const Pattern& p, double edge_length_m) {
  PatternMeshOptions options;
  options.edge_length_m = edge_length_m;
  return weld(pattern_garment(p, options));
}

// A field linear in the rest coordinates q, the same for every vertex with that q.
Vec3 linear(const Vec2& q) {
  return Vec3(0.3 + 2.0 * q.x() - q.y(), -0.1 + 0.5 * q.x() + 3.0 * q.y(), 0.7 * q.x() + 0.2);
}

// Every welded vertex's rest coordinates in the triangles' panel (one panel: unique).
std::vector<Vec2> rest_of_vertices(const SimulationMesh& mesh) {
  std::vector<Vec2> q(mesh.n_vertices, Vec2::Zero());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) q[mesh.triangles[t][k]] = mesh.rest_triangles[t][k];
  return q;
}

TEST(MeshTransfer, LinearFieldOnOnePanelArrivesExactly) {
  // aaron's front alone, cut on the fold: straight and curved edges (armhole, neck), so the
  // fine outline's points on a curve lie outside the coarse chords.
  Pattern p = aaron_bodice(TIGHTFIT_PATTERNS_DIR);
  p.panels.resize(1);
  p.seams.clear();
  const SimulationMesh coarse = meshed(p, 0.03), fine = meshed(p, 0.015);
  ASSERT_GT(fine.n_vertices, 3 * coarse.n_vertices);
  std::vector<Vec3> coarse_m;
  for (const Vec2& q : rest_of_vertices(coarse)) coarse_m.push_back(linear(q));
  const std::vector<Vec3> fine_m = transfer_positions(coarse, coarse_m, fine);
  const std::vector<Vec2> q = rest_of_vertices(fine);
  double largest = 0.0;
  for (int v = 0; v < fine.n_vertices; ++v)
    largest = std::max(largest, (fine_m[v] - linear(q[v])).norm());
  // Barycentric interpolation of a linear field is exact up to round-off (1e-16 of metres).
  EXPECT_LT(largest, 1e-12);
}

TEST(MeshTransfer, FlatLayoutOfTheSewnTopStaysARigidPlacement) {
  // Both panels of the top at 30 mm and 20 mm. The coarse welded vertices at a rotation and
  // shift of the front panel's rest coordinates: only the front's triangles are read there,
  // so the fine front vertices (those on no other panel) arrive at the same rigid placement.
  const Pattern p = aaron_bodice(TIGHTFIT_PATTERNS_DIR);
  const SimulationMesh coarse = meshed(p, 0.03), fine = meshed(p, 0.02);
  const auto placed = [](const Vec2& q) {
    const double c = std::cos(0.4), s = std::sin(0.4);
    return Vec3(c * q.x() - s * q.y() + 0.1, 0.2, s * q.x() + c * q.y() - 0.3);
  };
  // Front panel (0) rest coordinates of the coarse vertices; the back's do not matter.
  std::vector<Vec3> coarse_m(coarse.n_vertices, Vec3::Zero());
  for (std::size_t t = 0; t < coarse.triangles.size(); ++t)
    if (coarse.triangle_panel[t] == 0)
      for (int k = 0; k < 3; ++k)
        coarse_m[coarse.triangles[t][k]] = placed(coarse.rest_triangles[t][k]);
  const std::vector<Vec3> fine_m = transfer_positions(coarse, coarse_m, fine);
  std::vector<int> panels_of(fine.n_vertices, 0);  // bit p: on panel p
  std::vector<Vec2> front_q(fine.n_vertices, Vec2::Zero());
  for (std::size_t t = 0; t < fine.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int v = fine.triangles[t][k];
      panels_of[v] |= 1 << fine.triangle_panel[t];
      if (fine.triangle_panel[t] == 0) front_q[v] = fine.rest_triangles[t][k];
    }
  double largest = 0.0;
  int front_only = 0;
  for (int v = 0; v < fine.n_vertices; ++v)
    if (panels_of[v] == 1) {
      ++front_only;
      largest = std::max(largest, (fine_m[v] - placed(front_q[v])).norm());
    }
  EXPECT_GT(front_only, fine.n_vertices / 3);
  EXPECT_LT(largest, 1e-12);
}

TEST(MeshTransfer, RefusesMeshesOfDifferentGarmentsAndWrongSizes) {
  Pattern p = aaron_bodice(TIGHTFIT_PATTERNS_DIR);
  const SimulationMesh two = meshed(p, 0.03);
  p.panels.resize(1);
  p.seams.clear();
  const SimulationMesh one = meshed(p, 0.03);
  EXPECT_THROW(transfer_positions(two, std::vector<Vec3>(two.n_vertices), one),
               std::invalid_argument);
  EXPECT_THROW(transfer_positions(one, std::vector<Vec3>(3), one), std::invalid_argument);
}

}  // namespace
}  // namespace tightfit::pattern
