// Darts sewn as seams: FreeSewing's bella bodice front, cut on the fold, with its waist darts
// and bust darts sewn leg to leg. Each dart closes into the surface (one boundary loop round
// the whole front), its two legs get as many vertices and weld pairwise, its tip is one
// vertex, and no outline chord is a sliver (the mesher's points on one leg and their copies
// from the other are merged, edge_division.h).
#include "pattern/pattern_file.h"
#include "pattern/pattern_garment.h"
#include "tests/pattern/mesh_topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>

namespace tightfit::pattern {
namespace {

// bella's front (frontSideDart): 1 hem, 2-3 waist dart, 4 hem, 5 side, 6-7 bust dart, 8 side,
// 9-10 armhole, 11 shoulder, 12 neck, 13 centre front (the fold). The bust dart's legs are
// two different curves of one length (181.1 mm) meeting at 42 degrees.
Pattern bella_front() {
  Pattern p = read_pattern_file(std::string(TIGHTFIT_PATTERNS_DIR) +
                                "/freesewing_bella_cisFemaleAdult34_side_split.svg");
  p.panels.erase(std::remove_if(p.panels.begin(), p.panels.end(),
                                [](const PanelOutline& o) { return o.name != "frontSideDart"; }),
                 p.panels.end());
  p.panels.at(0).fold_edge = "13";
  p.seams = parse_seam_list(
      "frontSideDart:2 -- frontSideDart:3 reversed;"
      "frontSideDart:3 mirrored -- frontSideDart:2 mirrored reversed;"
      "frontSideDart:6 -- frontSideDart:7 reversed;"
      "frontSideDart:7 mirrored -- frontSideDart:6 mirrored reversed");
  return p;
}

TEST(Darts, BellaFrontDartsWeldLegToLegIntoOneSurface) {
  for (const double h : {0.02, 0.015}) {
    PatternMeshOptions options;
    options.edge_length_m = h;
    const Garment garment = pattern_garment(bella_front(), options);
    const SimulationMesh mesh = weld(garment);
    const MeshTopology top = topology(mesh);
    EXPECT_EQ(top.misoriented_edges, 0) << h;
    EXPECT_EQ(top.overused_edges, 0) << h;
    // The darts closed: only the front's outline is left open.
    EXPECT_EQ(top.boundary_loops.size(), 1u) << h;

    ASSERT_EQ(garment.seams.size(), 4u);
    const Panel& front = garment.panels.at(0);
    const int offset = mesh.panel_vertex_offset[0];
    for (const Seam& seam : garment.seams) {
      const std::vector<int>& a = front.edges.at(seam.edge_a);
      const std::vector<int>& b = front.edges.at(seam.edge_b);
      ASSERT_EQ(a.size(), b.size()) << seam.edge_a << " -- " << seam.edge_b;
      // Leg a along the outline, leg b against it (the seam's `reversed`): from the mouth the
      // legs weld vertex to vertex, the tip (the common end of the two legs) onto itself.
      EXPECT_TRUE(seam.reversed);
      for (std::size_t i = 0; i < a.size(); ++i) {
        const int ia = a[i];
        const int ib = b[seam.reversed ? b.size() - 1 - i : i];
        EXPECT_EQ(mesh.welded_index[offset + ia], mesh.welded_index[offset + ib])
            << seam.edge_a << " -- " << seam.edge_b << " vertex " << i;
      }
      // No sliver: the shortest chord on a leg against the target edge length.
      double shortest = std::numeric_limits<double>::infinity();
      for (const std::vector<int>* leg : {&a, &b})
        for (std::size_t i = 0; i + 1 < leg->size(); ++i)
          shortest = std::min(
              shortest,
              (front.rest_positions_m[(*leg)[i + 1]] - front.rest_positions_m[(*leg)[i]]).norm());
      EXPECT_GT(shortest, 0.25 * h) << seam.edge_a << " -- " << seam.edge_b;
    }
  }
}

}  // namespace
}  // namespace tightfit::pattern
