// GarmentCode files as GarmentCode writes them: circle flags as booleans or 0/1, the older bare
// [x, y] curvature, control points in absolute coordinates, null entries in panel_order; the
// jumpsuit read, meshed and sewn; a type error naming the panel, the edge and the key; a
// subset of panels keeping the stitches between them.
#include "pattern/pattern_file.h"
#include "pattern/pattern_garment.h"
#include "tests/pattern/mesh_topology.h"
#include "tests/pattern/pattern_files.h"
#include "tests/pattern/sewn_checks.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit::pattern {
namespace {

std::string data(const std::string& name) {
  return std::string(TIGHTFIT_PATTERN_TEST_DATA_DIR) + "/" + name;
}

// Signed distance of x to the left of the line start -> end.
double left_of(const Vec2& start, const Vec2& end, const Vec2& x) {
  const Vec2 d = (end - start).normalized();
  return d.x() * (x - start).y() - d.y() * (x - start).x();
}

TEST_F(PatternFiles, GarmentCodeCircleRightMeansTheArcBulgesRight) {
  // A semicircle of radius 1 from (0, 0) to (2, 0): GarmentCode's `right` puts the arc's
  // midpoint at relative y < 0, to the right of start -> end (its CircleEdge: right is
  // control_y < 0), here (1, -1); otherwise (1, 1). The panel closes with a straight top.
  for (const char* right : {"true", "1", "false", "0"}) {
    const bool is_right = std::string(right) == "true" || std::string(right) == "1";
    const std::string path =
        write("semicircle.json",
              std::string(R"({"pattern": {"panels": {"p": {"vertices": [[0, 0], [2, 0], [1, 3]],
        "edges": [{"endpoints": [0, 1], "curvature": {"type": "circle", "params": [1, 0, )") +
                  right + R"(]}}, {"endpoints": [1, 2]}, {"endpoints": [2, 0]}]}}},
        "properties": {"units_in_meter": 1}})");
    const Pattern p = read_pattern_file(path);
    const Segment& arc = p.panels[0].edges[0].segments[0];
    // Listed counter-clockwise, so kept as written (not mirrored).
    EXPECT_NEAR((point_at(arc, 0.5) - Vec2(1, is_right ? -1 : 1)).norm(), 0.0, 1e-12) << right;
    // The arc-length table (256 chords) is short of a half circle by pi^3 / (24 256^2), 2e-5.
    EXPECT_NEAR(length_m({arc}), M_PI - std::pow(M_PI, 3) / (24.0 * 256 * 256), 1e-9) << right;
  }
}

TEST_F(PatternFiles, GarmentCodeTypeErrorNamesPanelEdgeAndKey) {
  const std::string path = write("bad_flag.json", R"({"pattern": {"panels": {"front": {
      "vertices": [[0, 0], [2, 0], [1, 3]],
      "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2], "curvature": {"type": "circle",
                "params": [5, "no", 0]}}, {"endpoints": [2, 0]}]}}}})");
  try {
    read_pattern_file(path);
    FAIL() << "a flag that is a string was accepted";
  } catch (const PatternError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("panel 'front' edge 1: 'params[1] (large arc)' must be true/false or "
                        "0/1, not string"),
              std::string::npos)
        << error.what();
  }
  const std::string two = write("two.json", R"({"pattern": {"panels": {"front": {
      "vertices": [[0, 0], [2, 0], [1, 3]],
      "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2], "curvature": {"type": "circle",
                "params": [5, 2, 0]}}, {"endpoints": [2, 0]}]}}}})");
  EXPECT_THROW(read_pattern_file(two), PatternError);
  const std::string vertex = write("vertex.json", R"({"pattern": {"panels": {"front": {
      "vertices": [[0, 0], [2, "x"], [1, 3]], "edges": []}}}})");
  try {
    read_pattern_file(vertex);
    FAIL();
  } catch (const PatternError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("panel 'front' vertex 1: 'vertices' must be a number, not string"),
              std::string::npos)
        << error.what();
  }
}

TEST_F(PatternFiles, GarmentCodeAbsoluteControlPointsMatchRelativeOnes) {
  // The same quadratic edge from (0, 0) to (2, 0), its control point at (1, -0.5): relative
  // [0.5, -0.25] (a quarter of the edge's length to its right), absolute [1, -0.5].
  auto edge_midpoint = [&](const char* coords, const char* control) {
    const std::string path = write(
        "q.json", std::string(R"({"pattern": {"panels": {"p": {"vertices": [[0, 0], [2, 0], [1, 3]],
        "edges": [{"endpoints": [0, 1], "curvature": )") +
                      control + R"(}, {"endpoints": [1, 2]}, {"endpoints": [2, 0]}]}}},
        "properties": {"units_in_meter": 1, "curvature_coords": ")" +
                      coords + R"("}})");
    return point_at(read_pattern_file(path).panels[0].edges[0].segments[0], 0.5);
  };
  // A quadratic's midpoint is (start + 2 control + end) / 4 = (1, -0.25).
  for (const Vec2& m :
       {edge_midpoint("relative", R"({"type": "quadratic", "params": [[0.5, -0.25]]})"),
        edge_midpoint("relative", "[0.5, -0.25]"),
        edge_midpoint("absolute", R"({"type": "quadratic", "params": [[1, -0.5]]})")})
    EXPECT_NEAR((m - Vec2(1, -0.25)).norm(), 0.0, 1e-15);
}

TEST(GarmentCodeForms, EveryCurvatureFormReadsMeshesAndSews) {
  Pattern p = read_pattern_file(data("garmentcode_every_curvature.json"));
  ASSERT_EQ(p.panels.size(), 2u);  // panel_order's null skipped
  EXPECT_EQ(p.seams.size(), 3u);
  const PanelOutline& front = find_panel(p, "front");
  // Edges 4 and 5 are the same small circle (radius 15 cm) written with booleans and with
  // 0/1: each arc's sagitta is r - sqrt(r^2 - c^2 / 4), to the left of the edge (inwards).
  for (int e : {4, 5}) {
    const Segment& arc = front.edges[e].segments[0];
    const double c = (arc.end - arc.start).norm(), r = 0.15;
    EXPECT_NEAR(left_of(arc.start, arc.end, point_at(arc, 0.5)), r - std::sqrt(r * r - c * c / 4),
                1e-12)
        << "edge " << e;
  }
  // The bare [0.5, -0.1] of edge 2 is a quadratic whose midpoint lies half its control's
  // offset (3 cm) to the right: 1.5 cm outside the x = 40 cm side.
  const Segment& bare = front.edges[2].segments[0];
  EXPECT_EQ(bare.kind, Segment::Kind::quadratic);
  EXPECT_NEAR(point_at(bare, 0.5).x(), 0.415, 1e-15);
  validate(p);
  expect_sews_into(p, 0.01, 2);  // sewn at both sides: the hem and the top
}

TEST(GarmentCodeForms, JumpsuitReadsMeshesAndSews) {
  Pattern p = read_pattern_file(std::string(TIGHTFIT_PATTERNS_DIR) +
                                "/garmentcode_jumpsuit_mean_all_specification.json");
  ASSERT_EQ(p.panels.size(), 12u);
  EXPECT_EQ(p.seams.size(), 57u);
  validate(p);
  // The front neckline (right_ftorso edge 1, circle [9.47, 0, 0]: not right) dips into the
  // front, to the left of its edge, by its sagitta r - sqrt(r^2 - c^2 / 4).
  const PanelOutline& front = find_panel(p, "right_ftorso");
  const Segment& neck = front.edges[1].segments[0];
  const double r = 0.09471968255871255, c = (neck.end - neck.start).norm();
  EXPECT_NEAR(left_of(neck.start, neck.end, point_at(neck, 0.5)), r - std::sqrt(r * r - c * c / 4),
              1e-12);
  expect_sews_into(p, 0.03, 5);  // the neck, two wrists, two ankles
}

TEST(GarmentCodeForms, TorsoOfTheJumpsuitKeepsItsStitchesAndDropsTheOthers) {
  Pattern p = read_pattern_file(std::string(TIGHTFIT_PATTERNS_DIR) +
                                "/garmentcode_jumpsuit_mean_all_specification.json");
  const std::vector<std::string> torso{"right_ftorso", "left_ftorso", "right_btorso",
                                       "left_btorso"};
  const std::vector<std::string> dropped = keep_panels(p, torso);
  EXPECT_EQ(p.panels.size(), 4u);
  EXPECT_EQ(p.seams.size() + dropped.size(), 57u);
  for (const std::string& seam : dropped)
    EXPECT_TRUE(seam.find("sleeve") != std::string::npos || seam.find("pant") != std::string::npos)
        << seam;
  for (const SeamSpec& seam : p.seams)
    for (const EdgeRange* side : {&seam.a, &seam.b})
      EXPECT_NE(std::find(torso.begin(), torso.end(), side->panel), torso.end());
  validate(p);
  expect_sews_into(p, 0.03, 4);  // a vest: the neck, two armholes, the waist
  EXPECT_THROW(keep_panels(p, {"collar"}), PatternError);
}

}  // namespace
}  // namespace tightfit::pattern
