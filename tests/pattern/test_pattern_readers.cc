// The three readers on the shipped examples (sizes and lengths read off the files by hand),
// on hand-made files with every curve kind (lengths against closed forms), and on broken
// files (a message naming the element and why).
#include "pattern/pattern_file.h"
#include "pattern/pattern_garment.h"
#include "tests/pattern/mesh_topology.h"
#include "tests/pattern/pattern_files.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit::pattern {
namespace {

double edge_length(const Pattern& p, const std::string& panel, const std::string& edge) {
  const PanelOutline& outline = find_panel(p, panel);
  const int e = find_edge(outline, edge);
  EXPECT_GE(e, 0) << panel << ":" << edge;
  return e < 0 ? 0.0 : length_m(outline.edges[e].segments);
}

// Length of the parabola y = 2 h x (1 - x) over x in [0, 1] (a quadratic Bezier with its
// control at (1/2, h)): (sqrt(1 + k^2) + asinh(k) / k) / 2, k = 2 h.
double parabola_length(double h) {
  const double k = 2 * h;
  return 0.5 * (std::sqrt(1 + k * k) + std::asinh(k) / k);
}

// Sample-table accuracy of ArcLengthCurve (256 chords per segment) on these gentle curves.
constexpr double length_tolerance = 1e-6;

TEST_F(PatternFiles, GarmentCodeDressReadsSixPanelsAndTwentyThreeStitches) {
  const Pattern p = read_pattern_file(shipped("garmentcode_dress_pencil_specification.json"));
  ASSERT_EQ(p.panels.size(), 6u);
  EXPECT_EQ(p.seams.size(), 23u);
  // left_ftorso: vertex 1 at (28.69053, 0) cm; edge 0 a straight 28.69053 cm.
  EXPECT_NEAR(edge_length(p, "left_ftorso", "0"), 0.2869053, 1e-12);
  // The back panels are listed clockwise (seen from inside) and are mirrored to be seen from
  // outside; the front ones are kept.
  const PanelOutline& front = find_panel(p, "left_ftorso");
  EXPECT_NEAR(front.edges[1].segments[0].start.x(), 0.2869053, 1e-12);
  const PanelOutline& back = find_panel(p, "left_btorso");
  EXPECT_NEAR(back.edges[1].segments[0].start.y(), 0.5164782005173698, 1e-12);
  ASSERT_TRUE(front.placement.has_value());
  EXPECT_NEAR(front.placement->translation_m.z(), 0.30, 1e-12);
  validate(p);

  // Sewn: a sleeveless dress, one consistently oriented surface whose boundary is the neck,
  // two armholes and the hem.
  PatternMeshOptions options;
  options.edge_length_m = 0.03;
  const SimulationMesh mesh = weld(pattern_garment(p, options));
  const MeshTopology top = topology(mesh);
  EXPECT_EQ(top.misoriented_edges, 0);
  EXPECT_EQ(top.overused_edges, 0);
  EXPECT_EQ(top.boundary_loops.size(), 4u);
}

TEST_F(PatternFiles, GarmentCodeEveryCurveKind) {
  // A unit square in metres: a quadratic bottom bulging out by h = 0.3, a circular right edge
  // of radius 1 (chord 1: a 60-degree arc), a cubic top (the same parabola), a straight left.
  const std::string path = write("curves.json", R"({
    "pattern": {"panels": {"square": {
      "vertices": [[0, 0], [1, 0], [1, 1], [0, 1]],
      "edges": [
        {"endpoints": [0, 1], "curvature": {"type": "quadratic", "params": [[0.5, -0.3]]}},
        {"endpoints": [1, 2], "curvature": {"type": "circle", "params": [1.0, false, true]}},
        {"endpoints": [2, 3], "curvature": {"type": "cubic",
                                            "params": [[0.3333333333333333, -0.2], [0.6666666666666666, -0.2]]}},
        {"endpoints": [3, 0]}]}},
      "stitches": []},
    "properties": {"units_in_meter": 1}})");
  const Pattern p = read_pattern_file(path);
  EXPECT_NEAR(edge_length(p, "square", "0"), parabola_length(0.3), length_tolerance);
  EXPECT_NEAR(edge_length(p, "square", "1"), M_PI / 3, length_tolerance);
  EXPECT_NEAR(edge_length(p, "square", "2"), parabola_length(0.3), length_tolerance);
  EXPECT_NEAR(edge_length(p, "square", "3"), 1.0, 1e-15);
  // The bottom bulges out (below y = 0): its midpoint is at y = -h / 2.
  const Segment& bottom = find_panel(p, "square").edges[0].segments[0];
  EXPECT_NEAR(point_at(bottom, 0.5).y(), -0.15, 1e-15);
}

TEST_F(PatternFiles, SvgEveryPathCommand) {
  // 100 x 100 mm: relative line, H, V, a quadratic and a cubic (the same parabola, h = 30 mm
  // below the top edge once y is flipped), closed by Z. y points down in SVG.
  const std::string path =
      write("curves.svg", R"(<svg xmlns="http://www.w3.org/2000/svg" width="200mm">
    <g id="fs-stack-test.square-part-test.square">
      <path class="fabric" id="p" d="M 0,0 l 100,0 V 100 Q 50,130 0,100 C 0,66 0,33 0,0 z"/>
    </g></svg>)");
  const Pattern p = read_pattern_file(path);
  ASSERT_EQ(p.panels.size(), 1u);
  EXPECT_EQ(p.panels[0].name, "square");
  ASSERT_EQ(p.panels[0].edges.size(), 4u) << "Z closes on the start point: no fifth edge";
  EXPECT_NEAR(edge_length(p, "square", "1"), 0.1, 1e-15);
  EXPECT_NEAR(edge_length(p, "square", "2"), 0.1, 1e-15);
  EXPECT_NEAR(edge_length(p, "square", "3"), 0.1 * parabola_length(0.3), length_tolerance);
  EXPECT_NEAR(edge_length(p, "square", "4"), 0.1, 1e-12);
}

TEST_F(PatternFiles, FreeSewingAaronReadsItsFourPieces) {
  const Pattern p = read_pattern_file(shipped("freesewing_aaron_cisFemaleAdult34_outline.svg"));
  ASSERT_EQ(p.panels.size(), 4u);
  EXPECT_EQ(p.panels[0].name, "front");
  EXPECT_EQ(p.panels[1].name, "back");
  // front: fold (0,96)-(0,572), hem to (230.85,572), side, armhole, shoulder, neck (mm); the
  // back's repeated point (a zero-length L) is dropped, leaving six edges too.
  EXPECT_EQ(p.panels[0].edges.size(), 6u);
  EXPECT_EQ(p.panels[1].edges.size(), 6u);
  EXPECT_NEAR(edge_length(p, "front", "1"), 0.476, 1e-12);
  EXPECT_NEAR(edge_length(p, "front", "2"), 0.23085, 1e-12);
  EXPECT_NEAR(edge_length(p, "front", "5"), std::hypot(138.7 - 99.75, 17.35 - 7.89) * 1e-3, 1e-12);
  validate(p);
}

TEST_F(PatternFiles, AamaDxfReadsThePieceItsCornersAndGrain) {
  const Pattern p = read_pattern_file(shipped("clo_box_aama.dxf"));
  ASSERT_EQ(p.panels.size(), 1u);
  EXPECT_EQ(p.panels[0].name, "Pattern2D_4937");
  ASSERT_EQ(p.panels[0].edges.size(), 4u);  // four turn points
  // The first edge from (-0.107964, 0.143950) to (-0.010946, 78.883690) mm.
  EXPECT_NEAR(edge_length(p, "Pattern2D_4937", "1"),
              std::hypot(0.107964 - 0.010946, 78.883690 - 0.143950) * 1e-3, 1e-12);
  // The grain line on layer 7 runs along y: the warp vertical, the weft along x.
  EXPECT_NEAR(p.panels[0].grain_angle_rad, 0.0, 1e-12);
  validate(p);
}

TEST_F(PatternFiles, AamaDxfBulgeMakesAnArc) {
  // A half disc of radius 50 mm: a diameter, then back along a half circle (bulge 1).
  const std::string path =
      write("arc.dxf",
            "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n8\n0\n2\nhalf\n70\n0\n10\n0\n20\n0\n"
            "0\nPOLYLINE\n8\n1\n66\n1\n70\n1\n"
            "0\nVERTEX\n8\n1\n10\n-50\n20\n0\n"
            "0\nVERTEX\n8\n1\n10\n50\n20\n0\n42\n1\n"
            "0\nSEQEND\n0\nENDBLK\n0\nENDSEC\n0\nEOF\n");
  const Pattern p = read_pattern_file(path);
  ASSERT_EQ(p.panels.size(), 1u);
  ASSERT_EQ(p.panels[0].edges.size(), 2u);  // no turn points: every vertex a corner
  EXPECT_NEAR(edge_length(p, "half", "1"), 0.1, 1e-15);
  EXPECT_NEAR(edge_length(p, "half", "2"), 0.05 * M_PI, 0.05 * M_PI * 1e-5);
}

// A broken file must be refused with a message naming what and why.
struct BrokenFile {
  const char* name;
  const char* text;
  const char* message;
};

class BrokenPatternFiles : public PatternFiles, public ::testing::WithParamInterface<BrokenFile> {};

TEST_P(BrokenPatternFiles, AreRefusedWithAMessage) {
  const BrokenFile& f = GetParam();
  const std::string path = write(f.name, f.text);
  try {
    validate(read_pattern_file(path));
    FAIL() << f.name << " was accepted";
  } catch (const PatternError& error) {
    EXPECT_NE(std::string(error.what()).find(f.message), std::string::npos) << error.what();
  }
}

// Square panels in GarmentCode JSON, `edges` and `stitches` filled in per file.
#define SQUARE_JSON(EDGES, STITCHES)                                              \
  "{\"pattern\": {\"panels\": {\"a\": {\"vertices\": [[0,0],[1,0],[1,1],[0,1]], " \
  "\"edges\": " EDGES "}}, \"stitches\": " STITCHES "}, \"properties\": {\"units_in_meter\": 1}}"
#define SQUARE_EDGES                                                                          \
  "[{\"endpoints\": [0,1]}, {\"endpoints\": [1,2]}, {\"endpoints\": [2,3]}, {\"endpoints\": " \
  "[3,0]}]"

INSTANTIATE_TEST_SUITE_P(
    Readers, BrokenPatternFiles,
    ::testing::Values(
        BrokenFile{"truncated.json", "{\"pattern\": {\"panels\": {\"a\": {\"vertices\": [[0,",
                   "not valid JSON"},
        BrokenFile{"unknown_curve.json",
                   SQUARE_JSON("[{\"endpoints\": [0,1], \"curvature\": {\"type\": \"spline\", "
                               "\"params\": []}}, {\"endpoints\": [1,2]}, {\"endpoints\": [2,3]}, "
                               "{\"endpoints\": [3,0]}]",
                               "[]"),
                   "panel 'a' edge 0: unknown curvature 'spline'"},
        BrokenFile{"open.json",
                   SQUARE_JSON("[{\"endpoints\": [0,1]}, {\"endpoints\": [1,2]}, "
                               "{\"endpoints\": [2,3]}]",
                               "[]"),
                   "panel 'a': the outline is open between edge '2' and edge '0'"},
        BrokenFile{"missing_edge.json",
                   SQUARE_JSON(SQUARE_EDGES,
                               "[[{\"panel\": \"a\", \"edge\": 1}, "
                               "{\"panel\": \"a\", \"edge\": 9}]]"),
                   "stitch 0: panel 'a' has no edge 9"},
        BrokenFile{"zero_length.json",
                   "{\"pattern\": {\"panels\": {\"a\": {\"vertices\": [[0,0],[1,0],[1,0],[0,1]], "
                   "\"edges\": " SQUARE_EDGES "}}}, \"properties\": {\"units_in_meter\": 1}}",
                   "panel 'a', edge '1' has zero length"},
        BrokenFile{"truncated.svg", "<svg width=\"10mm\"><path class=\"fabric\" d=\"M 0,0 L",
                   "not valid XML"},
        BrokenFile{"arc.svg",
                   "<svg><path class=\"fabric\" id=\"p1\" d=\"M 0,0 L 10,0 R 5 5 0,0 z\"/></svg>",
                   "path 'p1' (panel 'p1'): unsupported path command 'R'"},
        BrokenFile{"no_piece.svg", "<svg><path class=\"mark\" d=\"M 0,0 L 1,1\"/></svg>",
                   "no <path class=\"fabric\"> element"},
        BrokenFile{"truncated.dxf",
                   "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n8\n0\n2\nbox\n70\n0\n10\n0\n20\n0\n"
                   "0\nPOLYLINE\n8\n1\n66\n1\n70\n1\n0\nVERTEX\n8\n1\n10\n0\n20\n0\n",
                   "block 'box': the boundary polyline is not finished"},
        BrokenFile{"open.dxf",
                   "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n8\n0\n2\nbox\n70\n0\n10\n0\n20\n0\n"
                   "0\nPOLYLINE\n8\n1\n66\n1\n70\n0\n0\nVERTEX\n8\n1\n10\n0\n20\n0\n"
                   "0\nVERTEX\n8\n1\n10\n10\n20\n0\n0\nVERTEX\n8\n1\n10\n10\n20\n10\n"
                   "0\nSEQEND\n0\nENDBLK\n0\nENDSEC\n0\nEOF\n",
                   "block 'box': the boundary is open"},
        BrokenFile{"spline_fit_points.dxf",
                   "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n8\n0\n2\nbox\n70\n0\n10\n0\n20\n0\n"
                   "0\nLINE\n8\n1\n10\n0\n20\n0\n11\n100\n21\n0\n"
                   "0\nSPLINE\n8\n1\n70\n8\n71\n3\n72\n0\n73\n0\n74\n2\n"
                   "11\n100\n21\n0\n11\n0\n21\n0\n0\nENDBLK\n0\nENDSEC\n0\nEOF\n",
                   "block 'box': SPLINE 2 is given by fit points only (2)"},
        BrokenFile{
            "two_loops.dxf",
            "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n8\n0\n2\nbox\n70\n0\n10\n0\n20\n0\n"
            "0\nLWPOLYLINE\n8\n1\n90\n3\n70\n1\n10\n0\n20\n0\n10\n100\n20\n0\n10\n0\n20\n100\n"
            "0\nLWPOLYLINE\n8\n1\n90\n3\n70\n1\n10\n200\n20\n0\n10\n300\n20\n0\n10\n200\n20\n100\n"
            "0\nENDBLK\n0\nENDSEC\n0\nEOF\n",
            "block 'box': LWPOLYLINE 1 is a closed loop of its own besides the other"},
        BrokenFile{
            "turn_point_off.dxf",
            "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n8\n0\n2\nbox\n70\n0\n10\n0\n20\n0\n"
            "0\nLWPOLYLINE\n8\n1\n90\n3\n70\n1\n10\n0\n20\n0\n10\n100\n20\n0\n10\n0\n20\n100\n"
            "0\nPOINT\n8\n2\n10\n50\n20\n50\n0\nENDBLK\n0\nENDSEC\n0\nEOF\n",
            "block 'box': the turn point (50, 50) is not on a vertex of the boundary"},
        BrokenFile{"unknown.pat", "", "unknown format '.pat'"}),
    [](const ::testing::TestParamInfo<BrokenFile>& info) {
      std::string name = info.param.name;
      for (char& c : name)
        if (c == '.') c = '_';
      return name;
    });

TEST(SeamList, ParsesSidesDirectionsAndRefusesMissingEdges) {
  const auto seams = parse_seam_list("front:3 -- back:3 mirrored reversed; front:4+5 -- back:4+5");
  ASSERT_EQ(seams.size(), 2u);
  EXPECT_EQ(seams[0].b.edges, std::vector<std::string>{"3 mirrored"});
  EXPECT_TRUE(seams[0].b.reversed);
  EXPECT_FALSE(seams[0].a.reversed);
  EXPECT_EQ(seams[1].a.edges, (std::vector<std::string>{"4", "5"}));
  EXPECT_THROW(parse_seam_list("front:3 back:3"), PatternError);

  Pattern p = read_pattern_file(shipped("freesewing_aaron_cisFemaleAdult34_outline.svg"));
  p.seams = parse_seam_list("front:3 -- back:7");
  try {
    validate(p);
    FAIL() << "a seam naming a missing edge was accepted";
  } catch (const PatternError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("seam 1 names edge '7' of panel 'back', which does not exist"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace tightfit::pattern
