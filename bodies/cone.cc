#include "bodies/cone.h"

#include "bodies/axis_frame.h"

#include <cmath>
#include <stdexcept>

namespace tightfit {

Cone::Cone(const ConeOptions& options) : options_(options), axis_(options.axis.normalized()) {
  if (!(options.axis.norm() > 0)) throw std::invalid_argument("Body/Axis: the cone axis is zero");
  if (!(options.half_angle_deg > 0 && options.half_angle_deg < 90))
    throw std::invalid_argument(
        "Body/Half angle: the cone's half-angle must lie in (0, 90) degrees");
  if (!(options.radius_at_point_m > 0))
    throw std::invalid_argument("Body/Radius: the cone radius must be positive (m)");
  set_radial_scale(1.0);
}

void Cone::set_radial_scale(double factor) {
  if (!(factor > 0)) throw std::invalid_argument("Body: the cone's radial scale must be positive");
  tan_half_angle_ = factor * std::tan(options_.half_angle_deg * M_PI / 180.0);
  radius_at_point_ = factor * options_.radius_at_point_m;
}

double Cone::half_angle_rad() const {
  return std::atan(tan_half_angle_);
}

// The apex's axial coordinate is -R0 / tan(alpha), whatever the radial scale.
Vec3 Cone::apex_m() const {
  return options_.point_on_axis_m - radius_at_point_ / tan_half_angle_ * axis_;
}

double Cone::radius_at_m(double axial_coordinate_m) const {
  return std::max(0.0, radius_at_point_ + axial_coordinate_m * tan_half_angle_);
}

SurfacePoint Cone::query(const Vec3& x) const {
  // In the meridian half-plane through x, with q = (s, rho) measured from the apex, the
  // surface is the ray along u = (cos a, sin a) and its outward normal is m = (-sin a, cos a).
  // Where q projects onto the ray (q.u >= 0) the distance is q.m and the normal m; behind the
  // apex the apex is closest.
  const double alpha = half_angle_rad(), c = std::cos(alpha), s_alpha = std::sin(alpha);
  const Vec3 from_apex = x - apex_m();
  const double s = from_apex.dot(axis_);
  const Vec3 radial = from_apex - s * axis_;
  const double rho = radial.norm();
  const Vec3 e_r = rho > 0 ? Vec3(radial / rho) : reference_direction_normal_to(axis_);
  SurfacePoint p;
  if (s * c + rho * s_alpha >= 0) {
    p.signed_distance_m = rho * c - s * s_alpha;
    p.outward_normal = c * e_r - s_alpha * axis_;
    // n depends on x only through e_r, which turns round the axis: dn/dx = cos(a) e_phi
    // e_phi^T / rho, the Hessian of the distance (curvature cos(a) / R at the foot, R = rho -
    // g cos(a)).
    if (rho > 0)
      p.normal_derivative_per_m =
          c * (Mat3::Identity() - axis_ * axis_.transpose() - e_r * e_r.transpose()) / rho;
  } else {
    p.signed_distance_m = from_apex.norm();
    p.outward_normal = from_apex / p.signed_distance_m;  // behind the apex x is never the apex
    p.normal_derivative_per_m =
        (Mat3::Identity() - p.outward_normal * p.outward_normal.transpose()) / p.signed_distance_m;
  }
  p.closest_point_m = x - p.signed_distance_m * p.outward_normal;
  p.gap_gradient = p.outward_normal;
  p.location.coordinates = Vec3((p.closest_point_m - options_.point_on_axis_m).dot(axis_),
                                angle_round_axis_rad(axis_, e_r), 0.0);
  return p;
}

Vec3 Cone::surface_point_m(const SurfaceLocation& location) const {
  const double s = location.coordinates[0];
  return options_.point_on_axis_m + std::max(s, -radius_at_point_ / tan_half_angle_) * axis_ +
         radius_at_m(s) * radial_direction(axis_, location.coordinates[1]);
}

DisplayMesh Cone::display_mesh() const {
  return revolution_display_mesh(*this, options_.display_length_m);
}

}  // namespace tightfit
