// The parts of a design that need no simulation (docs/design.md): the fabric's hoop force
// against the material law's closed forms, Laplace's law and its inverse, the refusal of a
// target the fabric cannot give, the targets of a compression class, and the cut (its
// circumferences, and its DXF and SVG read back by the pattern readers).
#include "cases/design/design_loop.h"
#include "cases/design/hoop_force.h"
#include "cases/design/stocking_cut.h"
#include "core/tensile_curves.h"
#include "pattern/pattern_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace tightfit {
namespace {

std::shared_ptr<const MaterialLaw> law(const std::string& name, const FabricParameters& f) {
  return make_material_law(name, f);
}

FabricParameters linear_fabric(double nu) {
  FabricParameters f;
  f.stiffness_weft_N_per_m = 300;
  f.stiffness_warp_N_per_m = 150;
  f.poisson_weft_warp = nu;
  return f;
}

// Linear Biot, nu12 = 0: the hoop force per rest width is Y1 (lambda - 1) whether the strip is
// free or held (docs/closed-forms.md, "A tube on a cone: Laplace's law"), to the bisection's 1e-12.
TEST(HoopForce, LinearBiotWithoutPoissonIsYTimesStrain) {
  for (HoopStrip strip : {HoopStrip::free, HoopStrip::held}) {
    const HoopForce hoop(law("linear biot", linear_fabric(0.0)), strip, 1.0);
    for (double lambda : {1.05, 1.25, 1.6}) {
      EXPECT_NEAR(hoop.force(lambda), 300 * (lambda - 1), 1e-9);
      EXPECT_NEAR(hoop.slope(lambda), 300, 1e-4);  // central difference of a straight line
    }
    EXPECT_EQ(hoop.force(0.9), 0.0);  // a slack ring presses nothing
  }
}

// Linear Biot with nu12: a free strip narrows and carries Y1 e; a strip held at its width
// carries Y1 e / (1 - nu12 nu21) (the plane-stress stiffness d11).
TEST(HoopForce, LinearBiotHeldStripIsStifferByThePoissonFactor) {
  const FabricParameters f = linear_fabric(0.3);
  const double d11 = 300 / (1 - f.poisson_weft_warp * f.poisson_warp_weft());
  const HoopForce free(law("linear biot", f), HoopStrip::free, 1.0);
  const HoopForce held(law("linear biot", f), HoopStrip::held, 1.0);
  EXPECT_NEAR(free.force(1.3), 300 * 0.3, 1e-8);
  EXPECT_NEAR(held.force(1.3), d11 * 0.3, 1e-8);
}

// The tensile-curves law: a free course strip reads Table 2's curve at its knots (24.5 N/m at
// 0.35, 49 N/m at 0.60); a held one the law's own held-strip tension
// (TensileCurves::held_weft_tension).
TEST(HoopForce, TensileCurvesReadTheCourseCurve) {
  const FabricParameters f;  // Table 2's curves
  const HoopForce free(law("tensile curves", f), HoopStrip::free, 0.6);
  const HoopForce held(law("tensile curves", f), HoopStrip::held, 0.6);
  EXPECT_NEAR(free.force(1.35), 24.5, 1e-9);
  EXPECT_NEAR(free.force(1.60), 49.0, 1e-9);
  const TensileCurves curves(f.tensile_curves());
  for (double e : {0.2, 0.35, 0.5})
    EXPECT_NEAR(held.force(1 + e), curves.held_weft_tension(e), 1e-9 * curves.held_weft_tension(e));
  EXPECT_NEAR(free.stretch_for(free.force(1.45)), 1.45, 1e-12);
  EXPECT_TRUE(std::isnan(free.stretch_for(49.5)));  // beyond the last knot
  EXPECT_EQ(known_largest_strain("tensile curves", f, 1.0), 0.6);
  EXPECT_EQ(known_largest_strain("linear biot", f, 0.8), 0.8);
}

// Eq. (1) and its inverse: p = N(g / c) 2 pi / g.
TEST(Laplace, PressureAndCircumferenceInvertEachOther) {
  const HoopForce hoop(law("linear biot", linear_fabric(0.0)), HoopStrip::held, 1.0);
  const double g = 0.30, c = 0.24;  // stretch 1.25
  EXPECT_NEAR(laplace_pressure_Pa(hoop, g, c), 300 * 0.25 * 2 * M_PI / g, 1e-9);
  EXPECT_NEAR(laplace_circumference_m(hoop, "C", g, laplace_pressure_Pa(hoop, g, c)), c, 1e-12);
}

// A target beyond the fabric's range is refused naming the band and the range: at most
// 300 N/m x 0.6 = 180 N/m, 2 pi 180 / 0.30 Pa = 28.3 mmHg on a 30 cm girth.
TEST(Laplace, RefusesATargetNoStrainInRangeGives) {
  const HoopForce hoop(law("linear biot", linear_fabric(0.0)), HoopStrip::held, 0.6);
  try {
    laplace_circumference_m(hoop, "C", 0.30, 40 * 133.322387415);
    FAIL() << "40 mmHg was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("band C"), std::string::npos) << what;
    EXPECT_NE(what.find("strain range (0 to 0.6)"), std::string::npos) << what;
    EXPECT_NE(what.find("at most 28.28 mmHg"), std::string::npos) << what;
  }
  EXPECT_THROW(laplace_circumference_m(hoop, "B", 0.30, 0.0), std::invalid_argument);
}

std::vector<NamedValue> stocking_points() {
  return {{"B", 0.02}, {"C", 0.24}, {"G", 0.55}};
}

// A class at B: the middle of RAL-GZ 387's range unless stated, times the profile's shares.
TEST(Targets, ClassAtBWithADegressiveProfile) {
  DesignTarget t;
  t.class_number = 2;
  t.profile = {{"B", 1.0}, {"C", 0.7}, {"G", 0.4}};
  const std::vector<double> p = target_pressures_mmHg(stocking_points(), t);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_DOUBLE_EQ(p[0], 27.5);  // (23 + 32) / 2
  EXPECT_DOUBLE_EQ(p[1], 0.7 * 27.5);
  EXPECT_DOUBLE_EQ(p[2], 0.4 * 27.5);
  t.class_number = 1;
  EXPECT_DOUBLE_EQ(target_pressures_mmHg(stocking_points(), t)[0], 19.5);
}

TEST(Targets, RefuseWhatNoClassOrProfileMeans) {
  DesignTarget t;
  t.class_number = 1;
  t.profile = {{"B", 1.0}, {"C", 0.7}, {"G", 0.4}};
  t.pressure_at_b_mmHg = 22;  // between class I and class II
  EXPECT_THROW(target_pressures_mmHg(stocking_points(), t), std::invalid_argument);
  t.pressure_at_b_mmHg = 0;
  t.profile = {{"B", 1.0}, {"C", 0.7}, {"G", 0.8}};  // rises at G
  try {
    target_pressures_mmHg(stocking_points(), t);
    FAIL() << "a rising profile was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not degressive"), std::string::npos) << e.what();
  }
  t.profile = {{"B", 1.0}, {"C", 0.7}};  // no share at G
  EXPECT_THROW(target_pressures_mmHg(stocking_points(), t), std::invalid_argument);
  t.class_number = 4;  // no upper bound: a pressure must be stated
  t.profile = {{"B", 1.0}, {"C", 0.7}, {"G", 0.4}};
  EXPECT_THROW(target_pressures_mmHg(stocking_points(), t), std::invalid_argument);
  EXPECT_THROW(design_point_heights({{"B", 0.3}, {"C", 0.2}}, 0.6), std::invalid_argument);
  EXPECT_THROW(parse_named_values("B:0.02, C", "Points"), std::invalid_argument);
}

// Points without a height take the body's landmarks' (a limb tube's case); a stated height is
// kept; a point with neither is refused, as is a name given twice.
TEST(Targets, PointsTakeTheLandmarksHeightsWhereNoneIsStated) {
  const std::vector<NamedValue> stated = parse_design_points("B, C:0.25, G", "Design/Points");
  ASSERT_EQ(stated.size(), 3u);
  EXPECT_TRUE(std::isnan(stated[0].value));
  EXPECT_EQ(stated[1].value, 0.25);
  const std::vector<NamedValue> landmarks = {{"B", 0.02}, {"C", 0.24}, {"G", 0.55}};
  const std::vector<NamedValue> heights = design_point_heights(stated, 0.6, landmarks);
  EXPECT_EQ(heights[0].value, 0.02);
  EXPECT_EQ(heights[1].value, 0.25);  // stated: not the landmark's 0.24
  EXPECT_EQ(heights[2].value, 0.55);
  EXPECT_THROW(design_point_heights(stated, 0.6), std::invalid_argument);  // no landmarks
  EXPECT_THROW(design_point_heights(parse_design_points("B, D", "P"), 0.6, landmarks),
               std::invalid_argument);  // D not found on the body
  EXPECT_THROW(parse_design_points("B, B:0.02", "P"), std::invalid_argument);
  EXPECT_THROW(parse_design_points("B C", "P"), std::invalid_argument);
}

PiecewiseLinear limb() {
  // A limb whose girth rises 20 cm to 40 cm over 0.5 m, with a bump at 0.25.
  return PiecewiseLinear({{0.0, 0.20}, {0.25, 0.33}, {0.5, 0.40}}, "limb");
}

// The cut: the design's circumference at each point, the ease linear between the points and
// applied to the limb's girth table.
TEST(Cut, FollowsTheLimbBetweenThePoints) {
  const std::vector<NamedValue> points = {{"B", 0.1}, {"G", 0.4}};
  const double gB = limb().at(0.1), gG = limb().at(0.4);
  const std::vector<CutKnot> cut = design_cut(limb(), points, {0.75 * gB, 0.85 * gG});
  ASSERT_EQ(cut.size(), 5u);  // 0, 0.1, 0.25, 0.4, 0.5
  EXPECT_EQ(cut[1].point, "B");
  EXPECT_NEAR(cut[1].circumference_m, 0.75 * gB, 1e-15);
  EXPECT_NEAR(cut[3].circumference_m, 0.85 * gG, 1e-15);
  EXPECT_NEAR(cut[2].circumference_m, 0.33 * (1 - 0.2), 1e-15);  // ease 0.25 and 0.15 halfway
  EXPECT_NEAR(cut[0].circumference_m, 0.20 * 0.75, 1e-15);       // constant ease below B
  EXPECT_NEAR(cut[4].circumference_m, 0.40 * 0.85, 1e-15);       // and above G
}

// The cut's DXF and SVG read back through tightfit's pattern readers: one piece whose bottom and
// top edges are the circumferences at the ends and whose sides run up the limb's knots.
TEST(Cut, DxfAndSvgReadBackAsThePiece) {
  const std::vector<NamedValue> points = {{"B", 0.1}, {"G", 0.4}};
  const std::vector<CutKnot> cut =
      design_cut(limb(), points, {0.75 * limb().at(0.1), 0.85 * limb().at(0.4)});
  double side = 0.0;
  for (std::size_t i = 1; i < cut.size(); ++i)
    side += std::hypot(cut[i].height_m - cut[i - 1].height_m,
                       0.5 * (cut[i].circumference_m - cut[i - 1].circumference_m));
  const auto dir = std::filesystem::temp_directory_path() / "tightfit_design_cut";
  std::filesystem::create_directories(dir);
  write_cut_dxf((dir / "cut.dxf").string(), "stocking", cut);
  const pattern::Pattern dxf = pattern::read_pattern_file((dir / "cut.dxf").string());
  ASSERT_EQ(dxf.panels.size(), 1u);
  const pattern::PanelOutline& piece = dxf.panels[0];
  EXPECT_EQ(piece.name, "stocking");
  ASSERT_EQ(piece.edges.size(), 4u);  // the four corners
  // Written in mm with 6 digits or more: lengths back to 1e-6 m.
  std::vector<double> lengths;
  for (const pattern::Edge& e : piece.edges) lengths.push_back(pattern::length_m(e.segments));
  std::sort(lengths.begin(), lengths.end());
  EXPECT_NEAR(lengths[0], cut.front().circumference_m, 1e-6);
  EXPECT_NEAR(lengths[1], cut.back().circumference_m, 1e-6);
  EXPECT_NEAR(lengths[2], side, 1e-6);
  EXPECT_NEAR(lengths[3], side, 1e-6);

  write_cut_svg((dir / "cut.svg").string(), "stocking", cut);
  const pattern::Pattern svg = pattern::read_pattern_file((dir / "cut.svg").string());
  ASSERT_EQ(svg.panels.size(), 1u);
  double perimeter = 0.0;
  for (const pattern::Edge& e : svg.panels[0].edges) perimeter += pattern::length_m(e.segments);
  // Written with 3 decimals in mm: each of the 10 segments within 1e-6 m.
  EXPECT_NEAR(perimeter, cut.front().circumference_m + cut.back().circumference_m + 2 * side, 1e-5);
}

}  // namespace
}  // namespace tightfit
