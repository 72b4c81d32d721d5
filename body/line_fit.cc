#include "body/line_fit.h"

#include <Eigen/Eigenvalues>

#include <stdexcept>

namespace tightfit {

FittedLine fit_line(const std::vector<Vec3>& points, const Vec3& towards) {
  if (points.size() < 2) throw std::invalid_argument("a line needs two points");
  FittedLine line;
  for (const Vec3& p : points) line.point_m += p;
  line.point_m /= static_cast<double>(points.size());
  Mat3 scatter = Mat3::Zero();
  for (const Vec3& p : points) scatter += (p - line.point_m) * (p - line.point_m).transpose();
  if (!(scatter.trace() > 0)) throw std::invalid_argument("a line needs two distinct points");
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(scatter);
  line.direction = eigen.eigenvectors().col(2);  // the largest eigenvalue's
  if (line.direction.dot(towards) < 0) line.direction = -line.direction;
  return line;
}

}  // namespace tightfit
