// AAMA DXF files in the forms garment CAD writes them (scripts/write-aama-test-patterns.py
// writes them; the shapes are stated there): boundaries of several entities in any order,
// graded files with a block per piece and size, files without a unit, and a real gap. Each
// form is read, meshed and sewn; each refusal names what and where.
#include "pattern/bspline.h"
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

// The name of the edge of `panel` that starts at `x` (metres).
std::string edge_starting_at(const PanelOutline& panel, const Vec2& x) {
  for (const Edge& e : panel.edges)
    if ((e.segments.front().start - x).norm() < 1e-5) return e.name;
  ADD_FAILURE() << "no edge of '" << panel.name << "' starts at " << x.transpose();
  return "";
}

std::string error_of(const std::string& file, const PatternFileOptions& options = {}) {
  try {
    validate(read_pattern_file(file, options));
  } catch (const PatternError& error) {
    return error.what();
  }
  return "(accepted)";
}

double shoelace(const std::vector<Vec2>& corners) {
  double twice = 0;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Vec2& a = corners[k];
    const Vec2& b = corners[(k + 1) % corners.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

// The B-spline point at u by de Boor's recursion (independent of the knot insertion read).
Vec2 de_boor(int p, const std::vector<Vec2>& control, const std::vector<double>& knots, double u) {
  int k = p;
  while (k + 1 < static_cast<int>(control.size()) && knots[k + 1] <= u) ++k;
  std::vector<Vec2> d(control.begin() + k - p, control.begin() + k + 1);
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const int i = j + k - p;
      const double a = (u - knots[i]) / (knots[i + 1 + p - r] - knots[i]);
      d[j] = (1 - a) * d[j - 1] + a * d[j];
    }
  return d[p];
}

// The chained back's left side (scripts/write-aama-test-patterns.py, BACK_SPLINE), mm.
const std::vector<Vec2> back_spline{Vec2(0, 500), Vec2(-40, 400), Vec2(-40, 250), Vec2(-40, 100),
                                    Vec2(0, 0)};
const std::vector<double> back_knots{0, 0, 0, 0, 0.5, 1, 1, 1, 1};

TEST(BsplineAsBezier, MatchesDeBoorOnClampedAndUnclampedKnots) {
  // Clamped (domain [0, 1], spans at 0.5) and uniform unclamped (domain [3, 5], spans at 4).
  struct Case {
    std::vector<double> knots, spans;
  };
  for (const Case& c :
       {Case{back_knots, {0, 0.5, 1}}, Case{{0, 1, 2, 3, 4, 5, 6, 7, 8}, {3, 4, 5}}}) {
    const auto segments = bspline_as_bezier_segments(3, back_spline, c.knots);
    ASSERT_EQ(segments.size(), 2u);
    for (std::size_t s = 0; s < 2; ++s)
      for (double t : {0.0, 0.3, 0.5, 0.9, 1.0}) {
        const double u = c.spans[s] + t * (c.spans[s + 1] - c.spans[s]);
        // Knot insertion is exact: round-off of a few operations on 100 mm numbers.
        EXPECT_NEAR((point_at(segments[s], t) - de_boor(3, back_spline, c.knots, u)).norm(), 0.0,
                    1e-9)
            << "span " << s << " t " << t;
      }
  }
  EXPECT_THROW(bspline_as_bezier_segments(3, back_spline, {0, 0, 1}), std::invalid_argument);
}

TEST(AamaForms, ChainedShuffledEntitiesReadMeshAndSew) {
  Pattern p = read_pattern_file(data("aama_chained_shuffled.dxf"));
  ASSERT_EQ(p.panels.size(), 2u);
  const PanelOutline& front = find_panel(p, "FRONT");
  const PanelOutline& back = find_panel(p, "BACK");
  // The front's six turn points make six edges; the back has none, its four entities make
  // four (joints as corners).
  ASSERT_EQ(front.edges.size(), 6u);
  ASSERT_EQ(back.edges.size(), 4u);
  const std::vector<Vec2> corners{Vec2(0, 0),      Vec2(0.4, 0),    Vec2(0.42, 0.3),
                                  Vec2(0.3, 0.56), Vec2(0.1, 0.56), Vec2(-0.02, 0.3)};
  // The joints are written 0.4 um off in x and y (the printed precision): a corner moves by
  // at most 0.57 um, an edge's length by at most 1.2 um.
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const std::string e = edge_starting_at(front, corners[k]);
    EXPECT_NEAR(length_m(front.edges[find_edge(front, e)].segments),
                (corners[(k + 1) % 6] - corners[k]).norm(), 1.2e-6);
  }
  // The back's neckline ARC: centre (200, 400) mm, from (400, 500) to (0, 500), radius
  // |(200, 100)|, sweep pi - 2 atan(1/2).
  const std::string neck = edge_starting_at(back, Vec2(0.4, 0.5));
  const double r = std::hypot(0.2, 0.1), sweep = M_PI - 2 * std::atan(0.5);
  // The arc-length table (256 chords a segment) is short of an arc by L sweep^2 / (24 256^2)
  // (1.54 um here); the radius is printed to 0.1 um and the angles to 1e-6 degrees (0.2 um).
  const double table = r * sweep * sweep * sweep / (24.0 * 256 * 256);
  EXPECT_NEAR(length_m(back.edges[find_edge(back, neck)].segments), r * sweep - table, 2e-7);
  // The SPLINE: two cubic Bezier spans, each through de Boor's points of the B-spline.
  const auto& side = back.edges[find_edge(back, edge_starting_at(back, Vec2(0, 0.5)))].segments;
  ASSERT_EQ(side.size(), 2u);
  for (std::size_t s = 0; s < 2; ++s)
    for (double t : {0.25, 0.5, 0.75}) {
      const Vec2 expected = 1e-3 * de_boor(3, back_spline, back_knots, 0.5 * (s + t));
      EXPECT_NEAR((point_at(side[s], t) - expected).norm(), 0.0, 1e-9);
    }

  // Sewn into a tube by its sides: the front's right side (two edges from (400, 0)) to the
  // back's SPLINE side walked up, the front's left side walked up to the back's right side.
  const std::string f_right1 = edge_starting_at(front, corners[1]),
                    f_right2 = edge_starting_at(front, corners[2]),
                    f_left1 = edge_starting_at(front, corners[5]),
                    f_left2 = edge_starting_at(front, corners[4]),
                    b_right = edge_starting_at(back, Vec2(0.4, 0)),
                    b_left = edge_starting_at(back, Vec2(0, 0.5));
  p.seams = parse_seam_list("FRONT:" + f_right1 + "+" + f_right2 + " -- BACK:" + b_left +
                            " reversed; FRONT:" + f_left1 + "+" + f_left2 +
                            " reversed -- BACK:" + b_right);
  validate(p);
  const Garment garment = expect_sews_into(p, 0.02, 2);  // a tube: the hem and the top
  // The front is a hexagon: its mesh's area is the shoelace area of its corners, to the
  // corners' 0.57 um times the perimeter.
  const Panel& front_mesh =
      garment.panels[0].name == "FRONT" ? garment.panels[0] : garment.panels[1];
  double perimeter = 0;
  for (std::size_t k = 0; k < 6; ++k) perimeter += (corners[(k + 1) % 6] - corners[k]).norm();
  EXPECT_NEAR(triangles_area(front_mesh), shoelace(corners), perimeter * 0.57e-6);
}

TEST(AamaForms, GradedFileListsItsSizesAndCutsTheOneChosen) {
  const std::string file = data("aama_graded_sizes.dxf");
  EXPECT_EQ(pattern_file_sizes(file), (std::vector<std::string>{"34", "36", "38"}));
  const std::string none = error_of(file);
  EXPECT_NE(none.find("the file holds 3 sizes: 34, 36, 38 (its sample size is 36); choose one"),
            std::string::npos)
      << none;
  const std::string unknown = error_of(file, {"40", ""});
  EXPECT_NE(unknown.find("no size '40' in the file (its sizes: 34, 36, 38)"), std::string::npos)
      << unknown;

  Pattern p = read_pattern_file(file, {"36", ""});
  ASSERT_EQ(p.panels.size(), 2u);
  // Size 36 is one size up from 34's 400 x 600 mm: 420 x 610 mm.
  for (const PanelOutline& panel : p.panels) {
    EXPECT_NEAR(length_m(panel.edges[0].segments), 0.42, 1e-12) << panel.name;
    EXPECT_NEAR(length_m(panel.edges[1].segments), 0.61, 1e-12) << panel.name;
  }
  p.seams = parse_seam_list("FRONT:2 -- BACK:4 reversed; FRONT:4 -- BACK:2 reversed");
  validate(p);
  for (const Panel& panel : expect_sews_into(p, 0.03, 2).panels)  // rectangles: exact areas
    EXPECT_NEAR(triangles_area(panel), 0.42 * 0.61, 1e-13);
}

TEST(AamaForms, FileWithoutUnitIsRefusedUnlessOneIsGiven) {
  const std::string file = data("aama_no_units.dxf");
  // 16 x 23.5 units: the largest piece 2.35 cm across in mm, implausible; the message says
  // what each unit gives.
  const std::string refused = error_of(file);
  EXPECT_NE(refused.find("names no unit (no $INSUNITS) and block 'TANK_FRONT' is 23.5 units "
                         "across: 2.35 cm in mm, 23.5 cm in cm, 59.69 cm in inches"),
            std::string::npos)
      << refused;
  Pattern p = read_pattern_file(file, {"", "inch"});
  EXPECT_NEAR(length_m(find_panel(p, "FRONT").edges[0].segments), 16 * 0.0254, 1e-15);
  EXPECT_NEAR(length_m(find_panel(p, "FRONT").edges[1].segments), 23.5 * 0.0254, 1e-15);
  p.seams = parse_seam_list("FRONT:2 -- BACK:4 reversed; FRONT:4 -- BACK:2 reversed");
  validate(p);
  for (const Panel& panel : expect_sews_into(p, 0.03, 2).panels)
    EXPECT_NEAR(triangles_area(panel), 16 * 23.5 * 0.0254 * 0.0254, 1e-13);
  // A file that states its unit is not overridden.
  const std::string clash = error_of(data("aama_graded_sizes.dxf"), {"34", "inch"});
  EXPECT_NE(clash.find("the file says its unit ($INSUNITS 4), which is not the inch asked for"),
            std::string::npos)
      << clash;
}

TEST(AamaForms, RealGapIsRefusedNamingTheBlockTheEndsAndTheGap) {
  const std::string refused = error_of(data("aama_gap.dxf"));
  EXPECT_NE(refused.find("block 'FRONT_M'"), std::string::npos) << refused;
  EXPECT_NE(refused.find("(100, 560)"), std::string::npos) << refused;
  EXPECT_NE(refused.find("(105, 560)"), std::string::npos) << refused;
  EXPECT_NE(refused.find(", 5 a"), std::string::npos) << refused;  // "5 away" or "5 apart"
}

// A file written the way other CAD systems write AAMA: "Piece Name:" and "Size:" in mixed case,
// the boundary one closed LWPOLYLINE repeating its first vertex, with a bulge (a sleeve cap),
// an internal line on layer 14, the piece placed by INSERT, $INSUNITS 1 (inches).
TEST_F(PatternFiles, AamaAsAnotherCadWritesItReadsInInches) {
  const std::string path = write("sleeve.dxf",
                                 "0\nSECTION\n"
                                 "2\nHEADER\n"
                                 "9\n$ACADVER\n"
                                 "1\nAC1009\n"
                                 "9\n$INSUNITS\n"
                                 "70\n1\n"
                                 "0\nENDSEC\n"
                                 "0\nSECTION\n"
                                 "2\nBLOCKS\n"
                                 "0\nBLOCK\n"
                                 "8\n0\n"
                                 "2\nSLEEVE-M\n"
                                 "70\n0\n"
                                 "10\n0.0\n"
                                 "20\n0.0\n"
                                 "0\nTEXT\n"
                                 "8\n1\n"
                                 "10\n1\n"
                                 "20\n1\n"
                                 "40\n0.2\n"
                                 "1\nPiece Name: Sleeve\n"
                                 "0\nTEXT\n"
                                 "8\n1\n"
                                 "10\n1\n"
                                 "20\n2\n"
                                 "40\n0.2\n"
                                 "1\nSize: M\n"
                                 "0\nLWPOLYLINE\n"
                                 "8\n1\n"
                                 "90\n5\n"
                                 "70\n1\n"
                                 "10\n0.0\n"
                                 "20\n0.0\n"
                                 "10\n14.0\n"
                                 "20\n0.0\n"
                                 "10\n15.5\n"
                                 "20\n16.0\n"
                                 "42\n0.35\n"
                                 "10\n-1.5\n"
                                 "20\n16.0\n"
                                 "10\n0.0\n"
                                 "20\n0.0\n"
                                 "0\nPOINT\n"
                                 "8\n2\n"
                                 "10\n0.0\n"
                                 "20\n0.0\n"
                                 "0\nPOINT\n"
                                 "8\n2\n"
                                 "10\n14.0\n"
                                 "20\n0.0\n"
                                 "0\nPOINT\n"
                                 "8\n2\n"
                                 "10\n15.5\n"
                                 "20\n16.0\n"
                                 "0\nPOINT\n"
                                 "8\n2\n"
                                 "10\n-1.5\n"
                                 "20\n16.0\n"
                                 "0\nLINE\n"
                                 "8\n7\n"
                                 "10\n7.0\n"
                                 "20\n2.0\n"
                                 "11\n7.0\n"
                                 "21\n14.0\n"
                                 "0\nPOLYLINE\n"
                                 "8\n14\n"
                                 "66\n1\n"
                                 "70\n0\n"
                                 "0\nVERTEX\n"
                                 "8\n14\n"
                                 "10\n7\n"
                                 "20\n8\n"
                                 "0\nVERTEX\n"
                                 "8\n14\n"
                                 "10\n8\n"
                                 "20\n8\n"
                                 "0\nSEQEND\n"
                                 "8\n14\n"
                                 "0\nENDBLK\n"
                                 "0\nENDSEC\n"
                                 "0\nSECTION\n"
                                 "2\nENTITIES\n"
                                 "0\nINSERT\n"
                                 "8\n0\n"
                                 "2\nSLEEVE-M\n"
                                 "10\n0\n"
                                 "20\n0\n"
                                 "0\nTEXT\n"
                                 "8\n0\n"
                                 "10\n0\n"
                                 "20\n0\n"
                                 "40\n0.2\n"
                                 "1\nUnits: ENGLISH\n"
                                 "0\nENDSEC\n"
                                 "0\nEOF\n");
  const Pattern p = read_pattern_file(path);
  ASSERT_EQ(p.panels.size(), 1u);
  EXPECT_EQ(p.panels[0].name, "Sleeve");
  ASSERT_EQ(p.panels[0].edges.size(), 4u);  // four turn points; the repeated vertex dropped
  EXPECT_NEAR(length_m(p.panels[0].edges[0].segments), 14 * 0.0254, 1e-15);
  // The cap: chord 17 in, bulge 0.35 (sweep 4 atan 0.35), radius chord / (2 sin(sweep / 2)),
  // less the arc-length table's deficit L sweep^2 / (24 256^2).
  const double sweep = 4 * std::atan(0.35), chord = 17 * 0.0254;
  const double arc = sweep * chord / (2 * std::sin(sweep / 2));
  EXPECT_NEAR(length_m(p.panels[0].edges[2].segments), arc * (1 - sweep * sweep / (24.0 * 65536)),
              1e-12);
  validate(p);
}

}  // namespace
}  // namespace tightfit::pattern
