#include "pattern/segment.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tightfit::pattern {

Segment line_segment(const Vec2& start, const Vec2& end) {
  Segment s;
  s.start = start;
  s.end = end;
  return s;
}

Segment quadratic_segment(const Vec2& start, const Vec2& control, const Vec2& end) {
  Segment s = line_segment(start, end);
  s.kind = Segment::Kind::quadratic;
  s.control1 = control;
  return s;
}

Segment cubic_segment(const Vec2& start, const Vec2& control1, const Vec2& control2,
                      const Vec2& end) {
  Segment s = line_segment(start, end);
  s.kind = Segment::Kind::cubic;
  s.control1 = control1;
  s.control2 = control2;
  return s;
}

Segment arc_segment_from_bulge(const Vec2& start, const Vec2& end, double bulge) {
  if (bulge == 0.0 || start == end) return line_segment(start, end);
  Segment s = line_segment(start, end);
  s.kind = Segment::Kind::arc;
  s.sweep_rad = 4.0 * std::atan(bulge);
  // The centre lies on the chord's bisector, at distance (c / 2) / tan(sweep / 2) from the
  // chord's midpoint, to the left of the chord for a counter-clockwise arc.
  const Vec2 chord = end - start;
  const Vec2 left(-chord.y(), chord.x());
  s.centre = 0.5 * (start + end) + 0.5 * left / std::tan(0.5 * s.sweep_rad);
  return s;
}

Vec2 point_at(const Segment& s, double t) {
  const double u = 1.0 - t;
  switch (s.kind) {
    case Segment::Kind::line:
      return u * s.start + t * s.end;
    case Segment::Kind::quadratic:
      return u * u * s.start + 2 * u * t * s.control1 + t * t * s.end;
    case Segment::Kind::cubic:
      return u * u * u * s.start + 3 * u * u * t * s.control1 + 3 * u * t * t * s.control2 +
             t * t * t * s.end;
    case Segment::Kind::arc: {
      if (t >= 1.0) return s.end;  // exact end, so that outlines close exactly
      const double angle = t * s.sweep_rad;
      const Vec2 r = s.start - s.centre;
      return s.centre + Eigen::Rotation2Dd(angle) * r;
    }
  }
  return s.start;
}

Segment transformed(const Segment& s, const Mat2& A, const Vec2& b) {
  Segment m = s;
  m.start = A * s.start + b;
  m.end = A * s.end + b;
  m.control1 = A * s.control1 + b;
  m.control2 = A * s.control2 + b;
  if (s.kind == Segment::Kind::arc) {
    // A similarity is a multiple of a rotation or of a reflection: A^T A = c I.
    const Mat2 AtA = A.transpose() * A;
    if (std::abs(AtA(0, 1)) > 1e-12 * AtA.norm() ||
        std::abs(AtA(0, 0) - AtA(1, 1)) > 1e-12 * AtA.norm())
      throw std::invalid_argument("a circular arc cannot be scaled unevenly");
    m.centre = A * s.centre + b;
    if (A.determinant() < 0) m.sweep_rad = -s.sweep_rad;
  }
  return m;
}

Segment reversed(const Segment& s) {
  Segment r = s;
  std::swap(r.start, r.end);
  if (s.kind == Segment::Kind::cubic) std::swap(r.control1, r.control2);
  if (s.kind == Segment::Kind::arc) r.sweep_rad = -s.sweep_rad;
  return r;
}

ArcLengthCurve::ArcLengthCurve(std::vector<Segment> segments, int samples_per_segment)
    : segments_(std::move(segments)), samples_(samples_per_segment) {
  if (segments_.empty()) throw std::invalid_argument("an edge needs at least one segment");
  cumulative_m_.push_back(0.0);
  for (const Segment& s : segments_) {
    Vec2 previous = s.start;
    for (int k = 1; k <= samples_; ++k) {
      const Vec2 x = point_at(s, static_cast<double>(k) / samples_);
      cumulative_m_.push_back(cumulative_m_.back() + (x - previous).norm());
      previous = x;
    }
  }
}

Vec2 ArcLengthCurve::point_at_fraction(double s) const {
  const double total = length_m();
  if (!(total > 0)) return segments_.front().start;
  const double target = std::clamp(s, 0.0, 1.0) * total;
  // The sample interval holding the target length, then linear in that interval's parameter.
  const auto it = std::upper_bound(cumulative_m_.begin(), cumulative_m_.end(), target);
  const std::size_t k =
      std::clamp<std::size_t>(it - cumulative_m_.begin(), 1, cumulative_m_.size() - 1);
  const double a = cumulative_m_[k - 1], b = cumulative_m_[k];
  const double within = b > a ? (target - a) / (b - a) : 0.0;
  const std::size_t segment = (k - 1) / samples_;
  const double t = ((k - 1) % samples_ + within) / samples_;
  return point_at(segments_[segment], t);
}

std::vector<double> ArcLengthCurve::joint_fractions() const {
  std::vector<double> joints{0.0};
  for (std::size_t s = 1; s < segments_.size(); ++s)
    joints.push_back(cumulative_m_[s * samples_] / length_m());
  joints.push_back(1.0);
  return joints;
}

}  // namespace tightfit::pattern
