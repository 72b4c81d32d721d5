// The size of a loaded body, printed and checked before anything is solved on it
// (docs/measuring-bodies.md, "The size check"): a body in millimetres read as metres is a thousand
// times too large, a person read with the wrong up axis lies along x or y.
#pragma once

#include "bodies/triangle_surface.h"

#include <string>

namespace tightfit {

struct BodyExtent {
  Vec3 min_m = Vec3::Zero(), max_m = Vec3::Zero();
  Vec3 size_m() const { return max_m - min_m; }
};

BodyExtent body_extent(const std::vector<Vec3>& vertices_m);

// "1.590 m tall (z) x 0.571 m wide (x) x 0.310 m deep (y)".
std::string describe_extent(const BodyExtent& extent);

// Any body a garment goes on: throws BodyMeasureError (body_measurements.h) when the body is
// larger than a person can be (over 4 m along an axis: the file's units are not metres),
// smaller than any garment's body (under 1 cm along every axis: likewise) or
// lies down (over 1.2 m across and more than twice as long across as it is tall: the up axis
// is not the file's). `what` starts the message (the file's name).
void check_body_size(const BodyExtent& extent, const std::string& what);

// A whole standing person (measured for landmarks): besides check_body_size, 0.4 to 2.6 m
// tall.
void check_standing_person(const BodyExtent& extent, const std::string& what);

}  // namespace tightfit
