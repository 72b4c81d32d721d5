// dR/dx of the FE backend's residual by central differences, column by column,
//   K_fd(:, j) = (R(x + h e_j) - R(x - h e_j)) / (2 h),
// the reference its assembled Newton tangent (FemBackend::linearise) is checked against.
#pragma once

#include "fem/fem_backend.h"

#include <Eigen/Core>

#include <vector>

namespace tightfit::testing {

inline Eigen::MatrixXd residual_jacobian(const FemBackend& backend,
                                         const std::vector<Vec3>& node_positions_m, double h_m) {
  const int n = 3 * static_cast<int>(node_positions_m.size());
  Eigen::MatrixXd K_fd(n, n);
  for (int j = 0; j < n; ++j) {
    std::vector<Vec3> xp = node_positions_m, xm = node_positions_m;
    xp[j / 3][j % 3] += h_m;
    xm[j / 3][j % 3] -= h_m;
    Eigen::VectorXd Rp, Rm;
    Eigen::MatrixXd unused;
    backend.linearise(xp, Rp, unused);
    backend.linearise(xm, Rm, unused);
    K_fd.col(j) = (Rp - Rm) / (2 * h_m);
  }
  return K_fd;
}

}  // namespace tightfit::testing
