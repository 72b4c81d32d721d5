// Patterns meshed and sewn: mesh areas against the outlines' areas, angles and edge lengths
// against the mesher's bounds, seams against vertex counts and even spacing (ease), folds and
// mirrored copies against area and orientation invariants.
#include "pattern/pattern_garment.h"
#include "pattern/polygon_mesher.h"
#include "tests/pattern/mesh_topology.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit::pattern {
namespace {

// A panel of straight edges through `corners` (counter-clockwise), edges named `names`.
PanelOutline polygon_panel(const std::string& name, const std::vector<Vec2>& corners,
                           const std::vector<std::string>& names) {
  PanelOutline panel;
  panel.name = name;
  for (std::size_t k = 0; k < corners.size(); ++k)
    panel.edges.push_back(
        {names[k], {line_segment(corners[k], corners[(k + 1) % corners.size()])}});
  return panel;
}

PanelOutline rectangle(const std::string& name, double width, double height) {
  return polygon_panel(name, {Vec2(0, 0), Vec2(width, 0), Vec2(width, height), Vec2(0, height)},
                       {"bottom", "right", "top", "left"});
}

double signed_area(const Panel& panel, const Triangle& t) {
  const Vec2 a = panel.rest_positions_m[t[1]] - panel.rest_positions_m[t[0]];
  const Vec2 b = panel.rest_positions_m[t[2]] - panel.rest_positions_m[t[0]];
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

double panel_area(const Panel& panel) {
  double area = 0;
  for (const Triangle& t : panel.triangles) area += signed_area(panel, t);
  return area;
}

TEST(PolygonMesher, RespectsAngleAndSizeBoundsAndCoversTheOutline) {
  // An L-shaped outline of area 0.2 x 0.2 - 0.1 x 0.1 = 0.03 m^2, chords of 1 cm.
  std::vector<Vec2> outline;
  const std::vector<Vec2> corners{Vec2(0, 0),     Vec2(0.2, 0),   Vec2(0.2, 0.1),
                                  Vec2(0.1, 0.1), Vec2(0.1, 0.2), Vec2(0, 0.2)};
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Vec2 a = corners[k], b = corners[(k + 1) % corners.size()];
    const int n = static_cast<int>(std::lround((b - a).norm() / 0.01));
    for (int i = 0; i < n; ++i) outline.push_back(a + (b - a) * i / n);
  }
  const double h = 0.015;
  const PolygonMesh mesh = mesh_polygon(outline, h, 28);
  double area = 0;
  for (const Triangle& t : mesh.triangles) {
    const Vec2 a = mesh.points_m[t[1]] - mesh.points_m[t[0]],
               b = mesh.points_m[t[2]] - mesh.points_m[t[0]];
    const double twice = a.x() * b.y() - a.y() * b.x();
    EXPECT_GT(twice, 0) << "every triangle counter-clockwise";
    area += 0.5 * twice;
  }
  EXPECT_NEAR(area, 0.03, 1e-15);
  const MeshQuality q = mesh_quality(mesh.points_m, mesh.triangles);
  EXPECT_GE(q.min_angle_deg, 28 - 1e-9);
  EXPECT_LE(q.max_edge_m, h * (1 + 1e-9));
  EXPECT_TRUE(mesh.added_on_outline.empty()) << "1 cm chords are short enough for 1.5 cm cells";
}

TEST(PatternGarment, SeamWithEaseGetsEqualCountsSpreadEvenly) {
  // Two panels sewn left to right along sides of 0.20 and 0.22 m: 10 % ease on the right one.
  Pattern pattern;
  pattern.name = "ease";
  pattern.panels = {rectangle("a", 0.1, 0.2), rectangle("b", 0.1, 0.22)};
  pattern.seams.push_back({{"a", {"right"}, false}, {"b", {"left"}, true}});
  PatternMeshOptions options;
  options.edge_length_m = 0.01;
  const Garment garment = pattern_garment(pattern, options);
  const auto& a = garment.panels[0].edges.at("right");
  const auto& b = garment.panels[1].edges.at("left");
  ASSERT_EQ(a.size(), b.size());
  // The ease spread evenly: chord i of b is 0.22 / 0.20 times chord i of a, all along (the
  // chords are equal but where the mesher split one, then both sides alike).
  const auto& ra = garment.panels[0].rest_positions_m;
  const auto& rb = garment.panels[1].rest_positions_m;
  for (std::size_t i = 0; i + 1 < a.size(); ++i)
    EXPECT_NEAR((rb[b[i + 1]] - rb[b[i]]).norm() / (ra[a[i + 1]] - ra[a[i]]).norm(), 1.1, 1e-12);
  // a runs up its right edge, b (reversed) down its left: the bottoms meet.
  EXPECT_NEAR(ra[a.front()].y(), 0.0, 1e-15);
  EXPECT_NEAR(rb[b.back()].y(), 0.0, 1e-15);
  const SimulationMesh mesh = weld(garment);
  const int n_unwelded = static_cast<int>(garment.panels[0].rest_positions_m.size() +
                                          garment.panels[1].rest_positions_m.size());
  EXPECT_EQ(mesh.n_vertices, n_unwelded - static_cast<int>(a.size()));
  EXPECT_NEAR(rest_area(mesh), 0.1 * 0.2 + 0.1 * 0.22, 1e-14);
  const MeshTopology top = topology(mesh);
  EXPECT_EQ(top.misoriented_edges, 0);
  EXPECT_EQ(top.overused_edges, 0);
  EXPECT_EQ(top.boundary_loops.size(), 1u);
}

TEST(PatternGarment, FoldDoublesTheHalfPieceAndMirrorKeepsItsArea) {
  // A trapezoid half piece, the fold its left edge x = 0: unfolded, twice the area.
  PanelOutline half =
      polygon_panel("front", {Vec2(0, 0.3), Vec2(0, 0), Vec2(0.2, 0), Vec2(0.15, 0.3)},
                    {"fold", "hem", "side", "neck"});
  half.fold_edge = "fold";
  PanelOutline sleeve =
      polygon_panel("sleeve", {Vec2(0, 0), Vec2(0.1, 0), Vec2(0.03, 0.1)}, {"cuff", "seam", "cap"});
  sleeve.mirrored_copy = true;
  Pattern pattern;
  pattern.name = "cut";
  pattern.panels = {half, sleeve};
  const Pattern cut = cut_pieces(pattern);
  ASSERT_EQ(cut.panels.size(), 3u);
  EXPECT_EQ(cut.panels[2].name, "sleeve mirrored");
  // hem and neck join their mirror images; the side gets a mirrored twin.
  std::vector<std::string> names;
  for (const Edge& e : cut.panels[0].edges) names.push_back(e.name);
  EXPECT_EQ(names, (std::vector<std::string>{"hem", "side", "neck", "side mirrored"}));

  PatternMeshOptions options;
  options.edge_length_m = 0.02;
  const Garment garment = pattern_garment(pattern, options);
  EXPECT_NEAR(panel_area(garment.panels[0]), 2 * 0.3 * (0.2 + 0.15) / 2, 1e-14);
  EXPECT_NEAR(panel_area(garment.panels[1]), 0.5 * 0.1 * 0.1, 1e-14);
  EXPECT_NEAR(panel_area(garment.panels[2]), 0.5 * 0.1 * 0.1, 1e-14);
  for (const Panel& panel : garment.panels)
    for (const Triangle& t : panel.triangles) EXPECT_GT(signed_area(panel, t), 0) << panel.name;
}

TEST(PatternGarment, EaseScalesAlongTheGrain) {
  // A 0.2 x 0.1 rectangle whose weft runs along y (grain angle 90 degrees): ease weft 0.9,
  // warp 0.8 make it 0.2 * 0.8 by 0.1 * 0.9.
  Pattern pattern;
  pattern.name = "ease";
  pattern.panels = {rectangle("a", 0.2, 0.1)};
  pattern.panels[0].grain_angle_rad = M_PI / 2;
  pattern.ease_weft = 0.9;
  pattern.ease_warp = 0.8;
  PatternMeshOptions options;
  options.edge_length_m = 0.02;
  const Garment garment = pattern_garment(pattern, options);
  Vec2 low = garment.panels[0].rest_positions_m[0], high = low;
  for (const Vec2& x : garment.panels[0].rest_positions_m) {
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
  }
  EXPECT_NEAR(high.x() - low.x(), 0.2 * 0.8, 1e-14);
  EXPECT_NEAR(high.y() - low.y(), 0.1 * 0.9, 1e-14);
}

TEST(PatternGarment, GridRectanglesReproduceTheTube) {
  // Two rectangles sewn into a ring mesh as make_tube_garment's grid, welded alike.
  Pattern pattern;
  pattern.name = "tube";
  pattern.panels = {rectangle("front", 0.1878, 0.24), rectangle("back", 0.1878, 0.24)};
  pattern.seams = {{{"front", {"right"}, false}, {"back", {"left"}, true}},
                   {{"back", {"right"}, false}, {"front", {"left"}, true}}};
  PatternMeshOptions options;
  options.rectangle_grid = MeshSpacing{0.008, 0.022};
  const SimulationMesh mesh = weld(pattern_garment(pattern, options));
  // 23 x 11 cells per panel (round(0.1878 / 0.008), round(0.24 / 0.022)), two panels sewn
  // into a ring: 2 * 23 columns of 12 vertices.
  EXPECT_EQ(mesh.n_vertices, 2 * 23 * 12);
  EXPECT_EQ(mesh.triangles.size(), 2u * 2 * 23 * 11);
  const MeshTopology top = topology(mesh);
  EXPECT_EQ(top.boundary_loops.size(), 2u);  // the two ends of the tube
  EXPECT_EQ(top.misoriented_edges, 0);
  EXPECT_EQ(mesh.vertex_groups.at("bottom").size(), 46u);
}

}  // namespace
}  // namespace tightfit::pattern
