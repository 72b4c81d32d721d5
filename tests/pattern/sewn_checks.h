// Checks of a pattern meshed and sewn, shared by the reader tests: every seam closes (its two
// sides welded vertex to vertex, lying at equal fractions of their lengths), each panel's mesh
// covers its outline (the triangles' area equals the shoelace area of the panel's boundary
// polygon, whose vertices lie on the outline's curves).
#pragma once

#include "core/garment.h"
#include "pattern/pattern_garment.h"
#include "tests/pattern/mesh_topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <vector>

namespace tightfit::pattern {

inline double triangles_area(const Panel& panel) {
  double area = 0;
  for (const Triangle& t : panel.triangles) {
    const Vec2 a = panel.rest_positions_m[t[1]] - panel.rest_positions_m[t[0]];
    const Vec2 b = panel.rest_positions_m[t[2]] - panel.rest_positions_m[t[0]];
    area += 0.5 * (a.x() * b.y() - a.y() * b.x());
  }
  return area;
}

// The panel's boundary polygon: its mesh edges used by one triangle, walked round.
inline double boundary_shoelace_area(const Panel& panel) {
  std::map<std::pair<int, int>, int> directed;
  for (const Triangle& t : panel.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  double twice = 0;
  for (const auto& [edge, count] : directed)
    if (!directed.count({edge.second, edge.first})) {
      const Vec2& a = panel.rest_positions_m[edge.first];
      const Vec2& b = panel.rest_positions_m[edge.second];
      twice += a.x() * b.y() - b.x() * a.y();
    }
  return 0.5 * twice;
}

// Every seam's two sides welded vertex to vertex.
inline void expect_every_seam_closed(const Garment& garment, const SimulationMesh& mesh) {
  for (std::size_t k = 0; k < garment.seams.size(); ++k) {
    const Seam& s = garment.seams[k];
    const std::vector<int>& a = garment.panels[s.panel_a].edges.at(s.edge_a);
    std::vector<int> b = garment.panels[s.panel_b].edges.at(s.edge_b);
    ASSERT_EQ(a.size(), b.size()) << "seam " << k + 1;
    if (s.reversed) std::reverse(b.begin(), b.end());
    const int offset_a = mesh.panel_vertex_offset[s.panel_a];
    const int offset_b = mesh.panel_vertex_offset[s.panel_b];
    for (std::size_t i = 0; i < a.size(); ++i)
      EXPECT_EQ(mesh.welded_index[offset_a + a[i]], mesh.welded_index[offset_b + b[i]])
          << "seam " << k + 1 << " (" << s.edge_a << " -- " << s.edge_b << "), vertex " << i;
  }
}

// Every panel's triangles cover its boundary polygon exactly (no hole, no overlap).
inline void expect_meshes_cover_outlines(const Garment& garment) {
  for (const Panel& panel : garment.panels) {
    const double polygon = boundary_shoelace_area(panel);
    // Sums of some thousand products of metre-sized coordinates: round-off near 1e-16 m^2
    // each; 1e-12 relative is far above it.
    EXPECT_NEAR(triangles_area(panel), polygon, 1e-12 * polygon) << panel.name;
  }
}

// Meshes `pattern` at edge length `h`, sews it and checks the result: every seam closed, every
// panel's mesh covering its outline, the welded surface consistently oriented, no edge of
// three triangles, and `boundary_loops` loops of free edges (hems, necks, cuffs).
inline Garment expect_sews_into(const Pattern& pattern, double h, std::size_t boundary_loops) {
  PatternMeshOptions options;
  options.edge_length_m = h;
  const Garment garment = pattern_garment(pattern, options);
  const SimulationMesh mesh = weld(garment);
  expect_every_seam_closed(garment, mesh);
  expect_meshes_cover_outlines(garment);
  const MeshTopology top = topology(mesh);
  EXPECT_EQ(top.misoriented_edges, 0);
  EXPECT_EQ(top.overused_edges, 0);
  EXPECT_EQ(top.boundary_loops.size(), boundary_loops);
  return garment;
}

}  // namespace tightfit::pattern
