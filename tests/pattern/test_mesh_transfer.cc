// A state carried from a coarse mesh of a pattern to a finer one (core/mesh_transfer.h): a
// position field linear in the rest (pattern) coordinates arrives exactly at every fine vertex,
// inside the coarse outline and where the fine outline bulges past its chords; on the sewn top
// a field that is one rigid placement of the flat layout of both panels stays one.
#include "core/mesh_transfer.h"
#include "core/tube_garment.h"
#include "pattern/pattern_garment.h"
#include "tests/pattern/aaron_bodice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
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

TEST(MeshTransfer, TubeWrappedWithoutStretchKeepsItsEdgesWithinTheChordBound) {
  // The paper's "T" tube (two 0.157 x 0.24 m panels sewn into a ring) meshed with cells of
  // w = 31.4 mm round it, wrapped without stretch round a cylinder of its own circumference
  // (layout x = u goes to the angle u / R, layout y to the height), and carried to cells half
  // as large. The coarse surface is a prism of flat facets, each a cell, the facets' normals
  // theta = w / R apart. Inside a facet the carried map is affine: it shortens across the axis
  // by the chord's share of its arc, s = sin(theta / 2) / (theta / 2), and keeps lengths along
  // it; two points on neighbouring facets at distances a and b from their common edge are at
  // least (a + b) cos(theta / 2) apart. So every carried edge keeps between s cos(theta / 2)
  // and 1 of its rest length (the chord of a path is no longer than the path).
  const double width_m = 0.157, height_m = 0.24;
  const SimulationMesh coarse =
      weld(make_tube_garment("T", width_m, height_m, 2, MeshSpacing{0.0314, 0.03}));
  const SimulationMesh fine =
      weld(make_tube_garment("T", width_m, height_m, 2, MeshSpacing{0.0157, 0.015}));
  const double radius_m = 2 * width_m / (2 * M_PI);
  std::vector<Vec3> coarse_m(coarse.n_vertices);
  for (int u = 0; u < coarse.n_unwelded_vertices(); ++u) {
    const Vec2& q = coarse.layout_positions_m[u];
    const double angle = q.x() / radius_m;
    coarse_m[coarse.welded_index[u]] =
        Vec3(radius_m * std::sin(angle), -radius_m * std::cos(angle), q.y());
  }
  const std::vector<Vec3> fine_m = transfer_positions(coarse, coarse_m, fine);
  const double theta = 0.0314 / radius_m;
  const double lowest = std::sin(theta / 2) / (theta / 2) * std::cos(theta / 2);
  double smallest = 2.0, largest = 0.0;
  for (std::size_t t = 0; t < fine.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = fine.triangles[t][k], b = fine.triangles[t][(k + 1) % 3];
      const double rest = (fine.rest_triangles[t][k] - fine.rest_triangles[t][(k + 1) % 3]).norm();
      const double ratio = (fine_m[a] - fine_m[b]).norm() / rest;
      smallest = std::min(smallest, ratio);
      largest = std::max(largest, ratio);
    }
  EXPECT_GE(smallest, lowest);
  EXPECT_LE(largest, 1.0 + 1e-12);
  std::printf("carried edges at %.6f to %.6f of their rest lengths; bound %.6f to 1\n", smallest,
              largest, lowest);
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
