#include "core/rigid_motion_fit.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace tightfit {

RigidMotionFit fit_rigid_motion(const std::vector<Vec3>& positions_m,
                                const std::vector<Vec3>& displacements_m) {
  if (positions_m.size() != displacements_m.size())
    throw std::invalid_argument("fit_rigid_motion: one displacement per position is needed");
  RigidMotionFit fit;
  if (positions_m.empty()) return fit;
  for (const Vec3& p : positions_m) fit.centre_m += p;
  fit.centre_m /= static_cast<double>(positions_m.size());
  // Normal equations of min sum |t + w x r_i - d_i|^2, r_i = p_i - c: with w x r = [r]^T w,
  // [r] the cross-product matrix of r, each point adds G_i^T G_i and G_i^T d_i, G_i = [I, [r]^T].
  using Mat6 = Eigen::Matrix<double, 6, 6>;
  using Vec6 = Eigen::Matrix<double, 6, 1>;
  Mat6 normal = Mat6::Zero();
  Vec6 right = Vec6::Zero();
  double total = 0.0;
  for (std::size_t i = 0; i < positions_m.size(); ++i) {
    const Vec3 r = positions_m[i] - fit.centre_m;
    Mat3 cross_transposed;  // [r]^T, so that cross_transposed * w = w x r
    cross_transposed << 0, r[2], -r[1], -r[2], 0, r[0], r[1], -r[0], 0;
    Eigen::Matrix<double, 3, 6> G;
    G << Mat3::Identity(), cross_transposed;
    normal += G.transpose() * G;
    right += G.transpose() * displacements_m[i];
    total += displacements_m[i].squaredNorm();
  }
  // Complete orthogonal decomposition: the least-norm solution where the points are collinear.
  const Vec6 q = normal.completeOrthogonalDecomposition().solve(right);
  fit.translation_m = q.head<3>();
  fit.rotation_rad = q.tail<3>();
  // The rigid field is the projection of d on the rigid motions: its squared norm is q . right.
  fit.explained = total > 0.0 ? std::clamp(q.dot(right) / total, 0.0, 1.0) : 0.0;
  return fit;
}

std::string text(const RigidMotionFit& fit) {
  const double angle = fit.rotation_rad.norm();
  const Vec3 axis = angle > 0.0 ? Vec3(fit.rotation_rad / angle) : Vec3::Zero();
  char line[240];
  std::snprintf(line, sizeof line,
                "%.0f%% a rigid motion: a turn of %.3g rad about (%.3f, %.3f, %.3f) through "
                "(%.3f, %.3f, %.3f) m, a shift of %.3g m",
                100.0 * fit.explained, angle, axis[0], axis[1], axis[2], fit.centre_m[0],
                fit.centre_m[1], fit.centre_m[2], fit.translation_m.norm());
  return line;
}

}  // namespace tightfit
