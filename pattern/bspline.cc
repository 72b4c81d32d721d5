#include "pattern/bspline.h"

#include <stdexcept>
#include <string>

namespace tightfit::pattern {

namespace {

// Inserts knot u once into (knots, points) of degree p: Boehm's algorithm. The span k is the
// last with knots[k] <= u < knots[k + 1] among the domain's spans.
void insert_knot(int p, double u, int k, std::vector<Vec2>& points, std::vector<double>& knots) {
  std::vector<Vec2> next(points.size() + 1);
  for (int j = 0; j < static_cast<int>(next.size()); ++j) {
    if (j <= k - p)
      next[j] = points[j];
    else if (j > k)
      next[j] = points[j - 1];
    else {
      const double a = (u - knots[j]) / (knots[j + p] - knots[j]);
      next[j] = (1 - a) * points[j - 1] + a * points[j];
    }
  }
  points = next;
  knots.insert(knots.begin() + k + 1, u);
}

int multiplicity(const std::vector<double>& knots, double u) {
  int m = 0;
  for (double k : knots) m += k == u;
  return m;
}

}  // namespace

std::vector<Segment> bspline_as_bezier_segments(int p, std::vector<Vec2> points,
                                                std::vector<double> knots) {
  const int n = static_cast<int>(points.size());
  if (p < 1 || p > 3)
    throw std::invalid_argument("a spline of degree " + std::to_string(p) +
                                " (degrees 1 to 3 are read)");
  if (n < p + 1)
    throw std::invalid_argument("a spline of degree " + std::to_string(p) + " needs " +
                                std::to_string(p + 1) + " control points, it has " +
                                std::to_string(n));
  if (static_cast<int>(knots.size()) != n + p + 1)
    throw std::invalid_argument(std::to_string(n) + " control points of degree " +
                                std::to_string(p) + " need " + std::to_string(n + p + 1) +
                                " knots, the spline has " + std::to_string(knots.size()));
  for (std::size_t k = 1; k < knots.size(); ++k)
    if (!(knots[k] >= knots[k - 1])) throw std::invalid_argument("the spline's knots decrease");
  const double first = knots[p], last = knots[n];
  if (!(last > first)) throw std::invalid_argument("the spline's domain is empty");
  // Every distinct knot of the domain, its ends included, to multiplicity p (at most 3 x the
  // knots inserted, each copying the control points: fine for the few knots of a pattern).
  std::vector<double> values;
  for (int k = p; k <= n; ++k)
    if (values.empty() || knots[k] != values.back()) values.push_back(knots[k]);
  for (double u : values) {
    while (multiplicity(knots, u) < p) {
      // The span holding u: the last k with knots[k] <= u, within the domain's spans.
      int k = p;
      while (k + 1 < static_cast<int>(points.size()) && knots[k + 1] <= u) ++k;
      insert_knot(p, u, k, points, knots);
    }
  }
  std::vector<Segment> segments;
  for (int i = p; i + 1 < static_cast<int>(knots.size()) - p; ++i) {
    if (!(knots[i + 1] > knots[i]) || knots[i] < first || knots[i + 1] > last) continue;
    const Vec2* b = &points[i - p];
    if (p == 1) segments.push_back(line_segment(b[0], b[1]));
    if (p == 2) segments.push_back(quadratic_segment(b[0], b[1], b[2]));
    if (p == 3) segments.push_back(cubic_segment(b[0], b[1], b[2], b[3]));
  }
  return segments;
}

}  // namespace tightfit::pattern
