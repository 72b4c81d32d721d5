// -d(force)/dx of a force on one vertex by central differences, column by column:
//   K(:, j) = -(f(x + h e_j) - f(x - h e_j)) / (2 h),
// the reference the analytic contact and friction tangents are checked against.
#pragma once

#include "core/types.h"

namespace tightfit::testing {

template <class Force>
Mat3 minus_force_jacobian(const Force& force_N, const Vec3& x_m, double h_m = 1e-7) {
  Mat3 K;
  for (int j = 0; j < 3; ++j) {
    const Vec3 e = h_m * Vec3::Unit(j);
    K.col(j) = -(force_N(x_m + e) - force_N(x_m - e)) / (2 * h_m);
  }
  return K;
}

}  // namespace tightfit::testing
