#include "instruments/stamp.h"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>

namespace tightfit {

PrintedStamp print_stamp(const SimulationMesh& mesh, const StampDefinition& stamp,
                         int n_outline_points) {
  PrintedStamp printed;
  printed.definition = stamp;
  auto locate = [&](const Vec2& rest) {
    const auto point = locate_on_panel(mesh, stamp.panel, rest);
    if (!point)
      throw std::invalid_argument("stamp '" + stamp.name + "' (radius " +
                                  std::to_string(stamp.radius_m) + " m) leaves panel " +
                                  std::to_string(stamp.panel));
    return *point;
  };
  printed.centre = locate(stamp.centre_m);
  for (int k = 0; k < n_outline_points; ++k) {
    const double theta = 2.0 * M_PI * k / n_outline_points;
    const Vec2 offset = stamp.radius_m * Vec2(std::cos(theta), std::sin(theta));
    printed.outline.push_back(locate(stamp.centre_m + offset));
    printed.outline_rest_m.push_back(offset);
  }
  return printed;
}

namespace {

// The smallest rotation taking unit vector a to unit vector b (Rodrigues).
Mat3 rotation_between(const Vec3& a, const Vec3& b) {
  const Vec3 v = a.cross(b);
  const double c = a.dot(b);
  Mat3 K;
  K << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return Mat3::Identity() + K + K * K / (1.0 + c);
}

}  // namespace

StampFit fit_stamp(const SimulationMesh& mesh, const std::vector<Vec3>& positions_m,
                   const PrintedStamp& stamp, const RigidBody& body) {
  StampFit fit;
  fit.centre_m = deformed_position(mesh, positions_m, stamp.centre);
  fit.normal = body.query(fit.centre_m).outward_normal;
  // An orthonormal tangent basis (e1, e2) at the centre.
  const Vec3 helper = std::abs(fit.normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 e1 = fit.normal.cross(helper).normalized();
  const Vec3 e2 = fit.normal.cross(e1);
  Eigen::Matrix<double, 2, 3> tangent;
  tangent << e1.transpose(), e2.transpose();

  // Least squares dy_k = A dX_k over the outline's short chords: each chord dx_k of the
  // deformed outline is turned with the body's normal at its midpoint onto the tangent plane
  // at the centre (dy_k, of the chord's length; exact on a developable body such as a
  // cylinder), dX_k its rest chord.
  const int n = static_cast<int>(stamp.outline.size());
  std::vector<Vec3> x(n);
  for (int k = 0; k < n; ++k) x[k] = deformed_position(mesh, positions_m, stamp.outline[k]);
  Mat2 yx = Mat2::Zero(), xx = Mat2::Zero();
  for (int k = 0; k < n; ++k) {
    const int next = (k + 1) % n;
    const Vec3 midpoint_normal = body.query(0.5 * (x[k] + x[next])).outward_normal;
    // The chord lies in a flat face, not quite across the body's normal: keep its length.
    const Vec3 dx = x[next] - x[k];
    const Vec2 turned = tangent * (rotation_between(midpoint_normal, fit.normal) * dx);
    const Vec2 dy = turned * (dx.norm() / turned.norm());
    const Vec2 dX = stamp.outline_rest_m[next] - stamp.outline_rest_m[k];
    yx += dy * dX.transpose();
    xx += dX * dX.transpose();
  }
  const Mat2 A = yx * xx.inverse();
  fit.deformation_gradient = tangent.transpose() * A;

  // Principal stretches: A = V diag(s) W^T; V in the tangent plane, W in pattern space.
  const Eigen::JacobiSVD<Mat2> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
  fit.stretch_max = svd.singularValues()[0];
  fit.stretch_min = svd.singularValues()[1];
  fit.direction_max = tangent.transpose() * svd.matrixU().col(0);
  fit.direction_min = tangent.transpose() * svd.matrixU().col(1);
  const Vec2 w = svd.matrixV().col(0);
  fit.grain_angle_max_deg = std::atan2(w.y(), w.x()) * 180.0 / M_PI;
  // A direction, not an arrow: report it in (-90, 90].
  if (fit.grain_angle_max_deg <= -90.0) fit.grain_angle_max_deg += 180.0;
  if (fit.grain_angle_max_deg > 90.0) fit.grain_angle_max_deg -= 180.0;
  return fit;
}

}  // namespace tightfit
