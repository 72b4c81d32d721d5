// Girths of analytic bodies against closed forms: an elliptic cylinder's section against
// Ramanujan's perimeter of an ellipse, a circular one against its inscribed polygon, a capped
// cylinder's extent along its axis.
#include "body/section_cutter.h"
#include "synthetic_body.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit {
namespace {

constexpr double pi = 3.14159265358979323846;

// Ramanujan's first approximation to an ellipse's perimeter (relative error below 1e-9 at
// b/a = 2/3, far below the polygon's own).
double ramanujan_perimeter(double a, double b) {
  return pi * (3 * (a + b) - std::sqrt((3 * a + b) * (a + 3 * b)));
}

TEST(SectionGirths, EllipticCylinderSectionIsRamanujansPerimeter) {
  const double a = 0.16, b = 0.11;
  const int n = 512;
  const TriangleSurface s =
      testing::elliptic_cylinder(Vec3(0, 0, 0.2), Vec3::UnitZ(), Vec3::UnitX(), 0.5, a, b, n);
  const SectionCutter cutter(s, Vec3::UnitZ());
  const std::vector<SectionLoop> loops = cutter.cut(0.43);
  ASSERT_EQ(loops.size(), 1u);
  // A polygon of n points inscribed in the ellipse falls short of its perimeter by about
  // (pi/n)^2/6 relative (3.8e-6 at n = 512): 1e-5 relative allows for it.
  EXPECT_NEAR(loops[0].perimeter_m, ramanujan_perimeter(a, b), 1e-5 * ramanujan_perimeter(a, b));
  // Convex: the tape (the hull) reads the section itself, to rounding.
  EXPECT_NEAR(loops[0].hull_perimeter_m, loops[0].perimeter_m, 1e-12);
  EXPECT_NEAR(loops[0].area_m2, pi * a * b, 1e-4 * pi * a * b);
  EXPECT_NEAR(loops[0].centroid_m.z(), 0.43, 1e-12);
  EXPECT_NEAR(loops[0].centroid_m.head<2>().norm(), 0.0, 1e-9);
}

TEST(SectionGirths, TiltedCircularCylinderCutNormalToItsAxis) {
  // A leg 10 degrees off the vertical, cut normal to its axis: the inscribed 128-gon's
  // perimeter 2 n r sin(pi / n) exactly (to rounding, 1e-12 m).
  const double r = 0.06, t = 10 * pi / 180;
  const Vec3 axis(std::sin(t), 0, std::cos(t));
  const int n = 128;
  const TriangleSurface s =
      testing::elliptic_cylinder(Vec3(0.1, 0, 0), axis, Vec3::UnitY(), 0.8, r, r, n);
  const SectionCutter cutter(s, axis);
  const std::vector<SectionLoop> loops = cutter.cut(0.4);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_NEAR(loops[0].hull_perimeter_m, 2 * n * r * std::sin(pi / n), 1e-12);
}

TEST(SectionGirths, CappedCylinderExtentAndEmptyPlanesBeyondIt) {
  const TriangleSurface s =
      testing::elliptic_cylinder(Vec3(0, 0, -0.3), Vec3::UnitZ(), Vec3::UnitX(), 1.1, 0.1, 0.1, 64);
  const SectionCutter cutter(s, Vec3::UnitZ());
  EXPECT_DOUBLE_EQ(cutter.lowest(), -0.3);
  EXPECT_NEAR(cutter.highest(), 0.8, 1e-15);
  EXPECT_TRUE(cutter.cut(-0.31).empty());
  EXPECT_TRUE(cutter.cut(0.81).empty());
  EXPECT_EQ(cutter.cut(0.0).size(), 1u);
}

TEST(SectionGirths, HullBridgesAHollow) {
  // Two overlapping cylinders side by side (a bust's two breasts): the section is their union,
  // longer than the tape round it, which bridges the hollows between them with two straight
  // lines: hull = 2 pi r + 2 d for two circles of radius r whose centres are d apart.
  const double r = 0.05, d = 0.06;
  const TriangleSurface s = testing::surface_union(
      {testing::elliptic_cylinder(Vec3(-d / 2, 0, 0), Vec3::UnitZ(), Vec3::UnitX(), 0.3, r, r, 256),
       testing::elliptic_cylinder(Vec3(d / 2, 0, 0.01), Vec3::UnitZ(), Vec3::UnitX(), 0.3, r, r,
                                  256)});
  const SectionCutter cutter(s, Vec3::UnitZ());
  const std::vector<SectionLoop> loops = cutter.cut(0.15);
  ASSERT_EQ(loops.size(), 1u);
  // The 256-gons fall short of the circles by (pi/256)^2/6 = 2.5e-5 relative: 1e-4 m allows.
  EXPECT_NEAR(loops[0].hull_perimeter_m, 2 * pi * r + 2 * d, 1e-4);
  EXPECT_GT(loops[0].perimeter_m, loops[0].hull_perimeter_m + 0.005);
}

}  // namespace
}  // namespace tightfit
