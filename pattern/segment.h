// The curves a pattern outline is drawn with: straight lines, quadratic and cubic Bezier
// curves and circular arcs, all in the pattern plane (metres).
#pragma once

#include "core/types.h"

#include <vector>

namespace tightfit::pattern {

struct Segment {
  enum class Kind { line, quadratic, cubic, arc };
  Kind kind = Kind::line;
  Vec2 start = Vec2::Zero();
  Vec2 end = Vec2::Zero();
  // Bezier control points: quadratic uses control1, cubic both.
  Vec2 control1 = Vec2::Zero();
  Vec2 control2 = Vec2::Zero();
  // Arc: centre and signed sweep from start to end (positive counter-clockwise), radians.
  Vec2 centre = Vec2::Zero();
  double sweep_rad = 0.0;
};

Segment line_segment(const Vec2& start, const Vec2& end);
Segment quadratic_segment(const Vec2& start, const Vec2& control, const Vec2& end);
Segment cubic_segment(const Vec2& start, const Vec2& control1, const Vec2& control2,
                      const Vec2& end);
// The circular arc from start to end with DXF's bulge b = tan(sweep / 4): b > 0 turns
// counter-clockwise, |b| = 1 is a half circle, b = 0 a straight line (returned as a line).
Segment arc_segment_from_bulge(const Vec2& start, const Vec2& end, double bulge);

// The point at curve parameter t in [0, 1] (the Bezier parameter; the angle fraction of an arc).
Vec2 point_at(const Segment& segment, double t);

// The segment under an affine map x -> A x + b (Bezier curves map exactly; an arc stays an arc
// only under a similarity, so a map that is not one throws std::invalid_argument).
Segment transformed(const Segment& segment, const Mat2& A, const Vec2& b);
Segment reversed(const Segment& segment);

// A chain of segments (one edge of an outline) parametrised by arc length: a table of
// `samples_per_segment` chords per segment, exact to O((kappa h)^2) in length.
class ArcLengthCurve {
 public:
  explicit ArcLengthCurve(std::vector<Segment> segments, int samples_per_segment = 256);
  double length_m() const { return cumulative_m_.back(); }
  // The point a fraction s in [0, 1] of the length along the chain.
  Vec2 point_at_fraction(double s) const;
  // Arc-length fractions of the joints between segments (0 and 1 included).
  std::vector<double> joint_fractions() const;

 private:
  std::vector<Segment> segments_;
  int samples_;
  std::vector<double> cumulative_m_;  // at every sample, over all segments
};

}  // namespace tightfit::pattern
