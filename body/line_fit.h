// The line through a set of points in the least-squares sense (their centroid and principal
// direction): a body part's axis through the centroids of its sections.
#pragma once

#include "core/types.h"

#include <vector>

namespace tightfit {

struct FittedLine {
  Vec3 point_m = Vec3::Zero();     // the points' centroid
  Vec3 direction = Vec3::UnitZ();  // unit, turned to have a positive dot with `towards`
  // The point of the line at height z (the line must not be horizontal).
  Vec3 at_height(double z_m) const {
    return point_m + (z_m - point_m.z()) / direction.z() * direction;
  }
};

// Throws std::invalid_argument for fewer than two distinct points.
FittedLine fit_line(const std::vector<Vec3>& points_m, const Vec3& towards);

}  // namespace tightfit
