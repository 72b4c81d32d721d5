// Outline curves against closed forms: arc lengths of circles and parabolas, arc geometry from
// DXF bulges, reflections of every curve kind.
#include "pattern/segment.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit::pattern {
namespace {

TEST(Segments, QuarterCircleFromBulgeHasLengthPiRadiusOverTwo) {
  // bulge = tan(sweep / 4); a quarter circle of radius 0.1 from (0.1, 0) to (0, 0.1) about 0.
  const Segment arc = arc_segment_from_bulge(Vec2(0.1, 0), Vec2(0, 0.1), std::tan(M_PI / 8));
  EXPECT_NEAR(arc.centre.norm(), 0.0, 1e-15);
  EXPECT_NEAR((point_at(arc, 0.5) - Vec2(0.1 * std::sqrt(0.5), 0.1 * std::sqrt(0.5))).norm(), 0,
              1e-15);
  // 256 chords per segment: relative length error (pi / 2 / 256)^2 / 24 = 1.5e-6.
  EXPECT_NEAR(ArcLengthCurve({arc}).length_m(), 0.05 * M_PI, 0.05 * M_PI * 2e-6);
}

TEST(Segments, ParabolaLengthMatchesClosedForm) {
  // Quadratic Bezier (0,0) (1/2,h) (1,0) is y = 2 h x (1 - x); its length is
  // int_0^1 sqrt(1 + k^2 (1 - 2x)^2) dx with k = 2h: (sqrt(1 + k^2) + asinh(k) / k) / 2.
  const double h = 0.3, k = 2 * h;
  const double exact = 0.5 * (std::sqrt(1 + k * k) + std::asinh(k) / k);
  const Segment q = quadratic_segment(Vec2(0, 0), Vec2(0.5, h), Vec2(1, 0));
  EXPECT_NEAR(ArcLengthCurve({q}).length_m(), exact, 1e-6);
  // The same parabola as a cubic (degree elevation: controls at 1/3 and 2/3 of the way).
  const Segment c =
      cubic_segment(Vec2(0, 0), Vec2(1.0 / 3, 2 * h / 3), Vec2(2.0 / 3, 2 * h / 3), Vec2(1, 0));
  for (double t : {0.1, 0.5, 0.77}) EXPECT_NEAR((point_at(c, t) - point_at(q, t)).norm(), 0, 1e-15);
}

TEST(Segments, ArcLengthFractionsAreEvenlySpaced) {
  const Segment arc = arc_segment_from_bulge(Vec2(1, 0), Vec2(-1, 0), 1.0);  // half circle
  const ArcLengthCurve curve({arc, line_segment(Vec2(-1, 0), Vec2(-1, -M_PI))});
  // Half circle of length pi, then a line of length pi: the middle is the joint. 256 chords
  // of pi / 256 rad each shorten the half circle by (pi / 256)^2 / 24 = 6.3e-6 of its length,
  // moving the joint by half that.
  EXPECT_NEAR(curve.length_m(), 2 * M_PI, 2.5e-5);
  EXPECT_NEAR(curve.joint_fractions()[1], 0.5, 4e-6);
  EXPECT_NEAR((curve.point_at_fraction(0.25) - Vec2(0, 1)).norm(), 0, 1e-5);
  EXPECT_NEAR((curve.point_at_fraction(0.75) - Vec2(-1, -M_PI / 2)).norm(), 0, 1e-5);
}

TEST(Segments, ReflectionKeepsArcsCirclesAndFlipsTheirTurn) {
  const Segment arc = arc_segment_from_bulge(Vec2(0.1, 0), Vec2(0, 0.1), 0.4);
  const Mat2 mirror = Vec2(-1, 1).asDiagonal();
  const Segment m = transformed(arc, mirror, Vec2::Zero());
  for (double t : {0.0, 0.3, 0.6, 1.0})
    EXPECT_NEAR((point_at(m, t) - mirror * point_at(arc, t)).norm(), 0, 1e-15);
  const Segment r = reversed(arc);
  for (double t : {0.0, 0.3, 1.0})
    EXPECT_NEAR((point_at(r, t) - point_at(arc, 1 - t)).norm(), 0, 1e-15);
  EXPECT_THROW(transformed(arc, Vec2(2, 1).asDiagonal(), Vec2::Zero()), std::invalid_argument);
}

}  // namespace
}  // namespace tightfit::pattern
