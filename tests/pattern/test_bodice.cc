// A sewn bodice: FreeSewing's aaron (a tank top), front and back cut on the fold, sewn at the
// sides and shoulders, welds into one consistently oriented surface whose boundary is four
// loops: the neck, two armholes and the hem, with no seam vertex left unmatched.
#include "pattern/pattern_garment.h"
#include "tests/pattern/aaron_bodice.h"
#include "tests/pattern/mesh_topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace tightfit::pattern {
namespace {

double loop_length(const SimulationMesh& mesh, const std::vector<int>& loop) {
  // Welded vertex -> a layout position is not one point for seam vertices; the rest length
  // of a boundary edge is, so walk each boundary edge's rest triangle.
  std::map<std::pair<int, int>, double> rest;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      rest[{mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]}] =
          (mesh.rest_triangles[t][(k + 1) % 3] - mesh.rest_triangles[t][k]).norm();
  double length = 0;
  for (std::size_t i = 0; i < loop.size(); ++i)
    length += rest.at({loop[i], loop[(i + 1) % loop.size()]});
  return length;
}

TEST(Bodice, AaronWeldsIntoOneSurfaceWithNeckArmholesAndHem) {
  const Pattern p = aaron_bodice(TIGHTFIT_PATTERNS_DIR);
  PatternMeshOptions options;
  options.edge_length_m = 0.015;
  const Garment garment = pattern_garment(p, options);
  const SimulationMesh mesh = weld(garment);
  const MeshTopology top = topology(mesh);
  EXPECT_EQ(top.misoriented_edges, 0);
  EXPECT_EQ(top.overused_edges, 0);
  ASSERT_EQ(top.boundary_loops.size(), 4u);

  // No unmatched seam vertex: apart from each seam's two ends, no vertex of a sewn edge lies
  // on the boundary (one would open a slit along the seam).
  std::set<int> boundary;
  for (const auto& loop : top.boundary_loops) boundary.insert(loop.begin(), loop.end());
  for (const Seam& seam : garment.seams) {
    const auto& a = garment.panels[seam.panel_a].edges.at(seam.edge_a);
    for (std::size_t i = 1; i + 1 < a.size(); ++i)
      EXPECT_EQ(boundary.count(mesh.welded_index[mesh.panel_vertex_offset[seam.panel_a] + a[i]]),
                0u)
          << garment.panels[seam.panel_a].name << ":" << seam.edge_a << " vertex " << i;
  }

  // The hem is straight: its loop is front and back hems, each unfolded (2 x 230.85 mm).
  std::vector<double> lengths;
  for (const auto& loop : top.boundary_loops) lengths.push_back(loop_length(mesh, loop));
  std::sort(lengths.begin(), lengths.end());
  EXPECT_NEAR(lengths.back(), 4 * 0.23085, 1e-12) << "the hem, the longest loop";
  // The two armholes: front and back armhole curves, equal on both sides; chords make them a
  // little shorter than the curves (by less than 1 %, measured 0.03 %).
  const double armhole = length_m(find_panel(p, "front").edges[3].segments) +
                         length_m(find_panel(p, "back").edges[3].segments);
  int armholes = 0;
  for (double l : lengths)
    if (l < armhole && l > 0.99 * armhole) ++armholes;
  EXPECT_EQ(armholes, 2);
}

}  // namespace
}  // namespace tightfit::pattern
