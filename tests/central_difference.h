// -d(force)/dx of a force on one vertex by central differences, column by column:
//   K(:, j) = -(f(x + h e_j) - f(x - h e_j)) / (2 h),
// the reference the analytic contact and friction tangents are checked against; and the
// gradient of an energy by the same differences, which a conservative force must equal with
// its sign changed.
#pragma once

#include "core/types.h"

#include <gtest/gtest.h>

#include <vector>

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

// Expects force[v][d] = -dE/dx[v][d] (the force of a potential energy E) at every vertex and
// direction, with E differentiated centrally, to `tolerance_N` (the difference's own error is
// h^2/6 times E's third derivative). Leaves x as it was.
template <class Energy>
void expect_force_is_minus_energy_gradient(std::vector<Vec3>& x, const std::vector<Vec3>& force_N,
                                           const Energy& energy_J, double tolerance_N,
                                           double h_m = 1e-7) {
  for (std::size_t v = 0; v < x.size(); ++v)
    for (int d = 0; d < 3; ++d) {
      const double saved = x[v][d];
      x[v][d] = saved + h_m;
      const double plus = energy_J(x);
      x[v][d] = saved - h_m;
      const double minus = energy_J(x);
      x[v][d] = saved;
      EXPECT_NEAR(force_N[v][d], -(plus - minus) / (2 * h_m), tolerance_N)
          << "vertex " << v << " direction " << d;
    }
}

}  // namespace tightfit::testing
