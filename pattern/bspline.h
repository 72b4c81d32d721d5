// A B-spline curve (a DXF SPLINE) as the chain of Bezier segments it is made of.
#pragma once

#include "pattern/segment.h"

#include <vector>

namespace tightfit::pattern {

// The non-rational B-spline of degree 1, 2 or 3 with these control points and knots (n + p + 1
// of them for n control points of degree p, non-decreasing), over its domain [u_p, u_n], as
// lines, quadratic or cubic Bezier segments, one per knot span of positive length. Exact: every
// interior knot is inserted (Boehm's algorithm) until it has multiplicity p, when the control
// points of each span are its Bezier points (Piegl & Tiller, The NURBS Book, 5.2 and 5.4).
// Throws std::invalid_argument for another degree or inconsistent knots.
std::vector<Segment> bspline_as_bezier_segments(int degree, std::vector<Vec2> control_points,
                                                std::vector<double> knots);

}  // namespace tightfit::pattern
