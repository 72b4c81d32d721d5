#include "massspring/positive_part.h"

#include <Eigen/Eigenvalues>

namespace tightfit {

namespace {

template <int N>
void clamp(Eigen::Matrix<double, N, N>& symmetric) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> eigen(symmetric);
  const auto& lambda = eigen.eigenvalues();
  if (lambda.minCoeff() >= 0.0) return;
  const auto& V = eigen.eigenvectors();
  symmetric = V * lambda.cwiseMax(0.0).asDiagonal() * V.transpose();
}

}  // namespace

Mat3 positive_part(const Mat3& block) {
  Mat3 symmetric = 0.5 * (block + block.transpose());
  clamp(symmetric);
  return symmetric;
}

void clamp_to_positive_part(Mat9& block) {
  clamp(block);
}

}  // namespace tightfit
