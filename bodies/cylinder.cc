#include "bodies/cylinder.h"

#include "bodies/axis_frame.h"

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
  e1_ = reference_direction_normal_to(axis_);
  e2_ = axis_.cross(e1_);
  across_axis_ = Mat3::Identity() - axis_ * axis_.transpose();
  set_radius(radius_m);
}

void Cylinder::set_radius(double radius_m) {
  if (!(radius_m > 0))
    throw std::invalid_argument("Body/Radius: the cylinder radius must be positive (m)");
  radius_m_ = radius_m;
}

SurfacePoint Cylinder::answer(const Vec3& x, QueryParts parts) const {
  const Vec3 from_axis = x - point_;
  const Vec3 radial = from_axis - from_axis.dot(axis_) * axis_;
  const double distance_to_axis = radial.norm();
  SurfacePoint s;
  // On the axis every direction is closest; pick the reference one.
  s.outward_normal = distance_to_axis > 0 ? Vec3(radial / distance_to_axis) : reference_direction();
  s.signed_distance_m = distance_to_axis - radius_m_;
  s.closest_point_m = x - s.signed_distance_m * s.outward_normal;
  s.gap_gradient = s.outward_normal;
  // The normal turns only round the axis: dn/dx = (I - a a^T - n n^T) / rho, the Hessian of
  // rho - R. On the axis itself it does not exist; zero is left there.
  if (parts.normal_derivative && distance_to_axis > 0)
    s.normal_derivative_per_m =
        (across_axis_ - s.outward_normal * s.outward_normal.transpose()) / distance_to_axis;
  // The angle as angle_round_axis_rad measures it, from the kept frame.
  if (parts.location)
    s.location.coordinates =
        Vec3(from_axis.dot(axis_), std::atan2(s.outward_normal.dot(e2_), s.outward_normal.dot(e1_)),
             0.0);
  return s;
}

Vec3 Cylinder::surface_point_m(const SurfaceLocation& location) const {
  return point_ + location.coordinates[0] * axis_ +
         radius_m_ * radial_direction(axis_, location.coordinates[1]);
}

Vec3 Cylinder::reference_direction() const {
  return e1_;
}

double Cylinder::angle_deg(const Vec3& x) const {
  double angle = angle_round_axis_rad(axis_, x - point_) * 180.0 / M_PI;
  if (angle < 0) angle += 360.0;
  return angle;
}

DisplayMesh Cylinder::display_mesh() const {
  return revolution_display_mesh(*this, display_height_m_);
}

}  // namespace tightfit
