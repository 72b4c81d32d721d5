// A tube cut to a limb from its measuring points (cases/limb_tube_cut.h) on a frustum of known
// radius at every height, along a tilted axis: the girth table against the closed form of the
// section (a regular polygon inscribed in the circle of radius r(s)), the tube's extent and the
// ease at the measuring points; and the entries' bad input.
#include "cases/limb_tube_cut.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit {
namespace {

constexpr double pi = 3.14159265358979323846;

// A frustum of `n` sides round the axis through `base` along unit `up`, radius r0 at the base
// growing by `slope` per metre up to `length`, capped at both ends, its faces outwards.
TriangleSurface frustum(const Vec3& base, const Vec3& up, double length, double r0, double slope,
                        int n) {
  const Vec3 u = up.unitOrthogonal(), v = up.cross(u);
  TriangleSurface s;
  for (int ring = 0; ring < 2; ++ring) {
    const double h = ring * length, r = r0 + slope * h;
    for (int k = 0; k < n; ++k) {
      const double t = 2 * pi * k / n;
      s.vertices_m.push_back(base + h * up + r * (std::cos(t) * u + std::sin(t) * v));
    }
  }
  const int bottom = static_cast<int>(s.vertices_m.size());
  s.vertices_m.push_back(base);
  s.vertices_m.push_back(base + length * up);
  for (int k = 0; k < n; ++k) {
    const int a = k, b = (k + 1) % n, c = n + k, d = n + (k + 1) % n;
    s.triangles.push_back({a, b, d});
    s.triangles.push_back({a, d, c});
    s.triangles.push_back({bottom, b, a});
    s.triangles.push_back({bottom + 1, c, d});
  }
  return s;
}

TEST(LimbTubeCut, GirthsOnAFrustumMatchTheClosedFormOfTheSection) {
  const Vec3 base(0.1, -0.02, 0.05), up = Vec3(0.12, 0.05, 1.0).normalized();
  const double r0 = 0.03, slope = 0.08, length = 0.7;
  const int n = 64;
  const TriangleSurface surface = frustum(base, up, length, r0, slope, n);
  // The measuring points at known distances up the axis from the base.
  const double s_base = up.dot(base);
  const std::vector<PointValue> points = {
      {"B", s_base + 0.10}, {"C", s_base + 0.33}, {"G", s_base + 0.58}};
  LimbTubeSpec spec;
  spec.from = parse_limb_tube_end("B - 0.02", "From");
  spec.to = parse_limb_tube_end("G + 0.04", "To");
  spec.negative_ease = parse_point_values("B: 0.25, G: 0.18", "Negative ease");
  const LimbTubeCut cut = cut_tube_along_axis(surface, base + 0.2 * up, up, points, spec);

  // Extent: from 2 cm below B to 4 cm above G (round-off only).
  EXPECT_NEAR(cut.length_m, 0.58 + 0.04 - 0.08, 1e-12);
  EXPECT_NEAR((cut.bottom_m - (base + 0.08 * up)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(cut.height_of("B"), 0.02, 1e-12);
  EXPECT_NEAR(cut.height_of("C"), 0.25, 1e-12);
  EXPECT_NEAR(cut.height_of("G"), 0.50, 1e-12);
  // Knots: both ends, every 5 cm, and B, C, G (a step within 5 mm of a point gives way).
  ASSERT_GE(cut.girths_m.points().size(), 13u);

  // The section normal to the axis is the regular n-gon inscribed in the circle of radius
  // r(s): its perimeter (and its hull's) 2 n r sin(pi / n), and the circle's 2 pi r exceeds it
  // by the polygon error 1 - n sin(pi / n) / pi = 4.0e-4 at n = 64. Each girth matches the
  // polygon to round-off (1e-9 m allowed: the plane's intersection points are computed in
  // floating point) and the circle within the polygon error (one-sided: the tape on the polygon
  // is shorter).
  const double polygon = n * std::sin(pi / n) / pi;
  for (const PiecewiseLinear::Point& k : cut.girths_m.points()) {
    const double r = r0 + slope * (0.08 + k.height_m);
    EXPECT_NEAR(k.value, 2 * pi * r * polygon, 1e-9) << "at H = " << k.height_m;
    EXPECT_LE(k.value, 2 * pi * r) << "at H = " << k.height_m;
    EXPECT_GE(k.value, 2 * pi * r * (1 - (1 - polygon) - 1e-12)) << "at H = " << k.height_m;
  }
  // The ease at the points as stated, linear between them.
  EXPECT_NEAR(cut.negative_ease.at(0.02), 0.25, 1e-12);
  EXPECT_NEAR(cut.negative_ease.at(0.50), 0.18, 1e-12);
  EXPECT_NEAR(cut.negative_ease.at(0.26), 0.5 * (0.25 + 0.18), 1e-12);
}

TEST(LimbTubeCut, RefusesEndsAndEasesItCannotPlace) {
  EXPECT_THROW(parse_limb_tube_end("Q - 0.02", "From"), std::invalid_argument);
  EXPECT_THROW(parse_limb_tube_end("B - two cm", "From"), std::invalid_argument);
  EXPECT_THROW(parse_limb_tube_end("B - -0.02", "From"), std::invalid_argument);
  EXPECT_THROW(parse_point_values("B: 0.25, B: 0.2", "Negative ease"), std::invalid_argument);
  EXPECT_THROW(parse_point_values("B 0.25", "Negative ease"), std::invalid_argument);
  const LimbTubeEnd plain = parse_limb_tube_end(" C ", "From");
  EXPECT_EQ(plain.point, "C");
  EXPECT_EQ(plain.offset_m, 0.0);

  const Vec3 up = Vec3::UnitZ();
  const TriangleSurface surface = frustum(Vec3::Zero(), up, 0.7, 0.03, 0.08, 32);
  const std::vector<PointValue> points = {{"B", 0.10}, {"C", 0.33}, {"G", 0.58}};
  LimbTubeSpec spec;
  spec.from = {"G", 0.0};
  spec.to = {"B", 0.0};  // upside down: no length
  EXPECT_THROW(cut_tube_along_axis(surface, Vec3::Zero(), up, points, spec), std::invalid_argument);
  spec.from = {"B", -0.02};
  spec.to = {"D", 0.0};  // not found on this limb
  EXPECT_THROW(cut_tube_along_axis(surface, Vec3::Zero(), up, points, spec), std::invalid_argument);
  spec.to = {"C", 0.0};
  spec.negative_ease = {{"G", 0.2}};  // G lies above the tube's top
  EXPECT_THROW(cut_tube_along_axis(surface, Vec3::Zero(), up, points, spec), std::invalid_argument);
  spec.negative_ease = {{"B", 1.2}};
  EXPECT_THROW(cut_tube_along_axis(surface, Vec3::Zero(), up, points, spec), std::invalid_argument);
  spec.negative_ease = {};
  spec.to = {"G", 0.5};  // beyond the limb's end: the plane misses it
  EXPECT_THROW(cut_tube_along_axis(surface, Vec3::Zero(), up, points, spec), BodyMeasureError);
}

}  // namespace
}  // namespace tightfit
