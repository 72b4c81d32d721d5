#include "contact/cylinder.h"

#include <Eigen/Geometry>  // Vec3::cross

#include <cmath>
#include <stdexcept>

namespace tightfit {

Cylinder::Cylinder(const Vec3& point_on_axis_m, const Vec3& axis, double radius_m,
                   double display_height_m)
    : point_(point_on_axis_m),
      axis_(axis.normalized()),
      radius_m_(0.0),
      display_height_m_(display_height_m) {
  if (!(axis.norm() > 0)) throw std::invalid_argument("Body/Axis: the cylinder axis is zero");
  set_radius(radius_m);
}

void Cylinder::set_radius(double radius_m) {
  if (!(radius_m > 0))
    throw std::invalid_argument("Body/Radius: the cylinder radius must be positive (m)");
  radius_m_ = radius_m;
}

SurfacePoint Cylinder::query(const Vec3& x) const {
  const Vec3 from_axis = x - point_;
  const Vec3 radial = from_axis - from_axis.dot(axis_) * axis_;
  const double distance_to_axis = radial.norm();
  SurfacePoint s;
  // On the axis every direction is closest; pick the reference one.
  s.outward_normal = distance_to_axis > 0 ? Vec3(radial / distance_to_axis) : reference_direction();
  s.signed_distance_m = distance_to_axis - radius_m_;
  s.closest_point_m = x - s.signed_distance_m * s.outward_normal;
  return s;
}

Vec3 Cylinder::reference_direction() const {
  // The unit vector normal to the axis nearest to +x (or +y when the axis is along x).
  const Vec3 seed = std::abs(axis_.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (seed - seed.dot(axis_) * axis_).normalized();
}

double Cylinder::angle_deg(const Vec3& x) const {
  const Vec3 e1 = reference_direction();
  const Vec3 e2 = axis_.cross(e1);
  const Vec3 d = x - point_;
  double angle = std::atan2(d.dot(e2), d.dot(e1)) * 180.0 / M_PI;
  if (angle < 0) angle += 360.0;
  return angle;
}

DisplayMesh Cylinder::display_mesh() const {
  // The paper's cylinder had 110 vertices (Table 3): 22 round by 5 along.
  const int n_round = 22, n_along = 5;
  const Vec3 e1 = reference_direction();
  const Vec3 e2 = axis_.cross(e1);
  DisplayMesh mesh;
  for (int j = 0; j < n_along; ++j) {
    const double s = display_height_m_ * (double(j) / (n_along - 1) - 0.5);
    for (int i = 0; i < n_round; ++i) {
      const double phi = 2.0 * M_PI * i / n_round;
      mesh.vertices_m.push_back(point_ + s * axis_ +
                                radius_m_ * (std::cos(phi) * e1 + std::sin(phi) * e2));
    }
  }
  for (int j = 0; j + 1 < n_along; ++j)
    for (int i = 0; i < n_round; ++i) {
      const int a = j * n_round + i, b = j * n_round + (i + 1) % n_round;
      mesh.triangles.push_back({a, b, b + n_round});
      mesh.triangles.push_back({a, b + n_round, a + n_round});
    }
  return mesh;
}

}  // namespace tightfit
