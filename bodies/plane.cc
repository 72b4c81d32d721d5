#include "bodies/plane.h"

#include <Eigen/Geometry>  // Vec3::cross

#include <stdexcept>

namespace tightfit {

Plane::Plane(const Vec3& point_m, const Vec3& outward_normal, double display_size_m)
    : point_(point_m), normal_(outward_normal.normalized()), display_size_m_(display_size_m) {
  if (!(outward_normal.norm() > 0))
    throw std::invalid_argument("Body/Normal: the plane normal is zero");
}

SurfacePoint Plane::query(const Vec3& x) const {
  SurfacePoint s;
  s.signed_distance_m = (x - point_).dot(normal_);
  s.outward_normal = normal_;
  s.closest_point_m = x - s.signed_distance_m * normal_;
  s.gap_gradient = normal_;  // a flat face: dn/dx stays zero
  const auto [e1, e2] = in_plane_axes();
  s.location.coordinates = Vec3((x - point_).dot(e1), (x - point_).dot(e2), 0.0);
  return s;
}

std::pair<Vec3, Vec3> Plane::in_plane_axes() const {
  const Vec3 seed = std::abs(normal_.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 e1 = (seed - seed.dot(normal_) * normal_).normalized();
  return {e1, normal_.cross(e1)};
}

Vec3 Plane::surface_point_m(const SurfaceLocation& location) const {
  const auto [e1, e2] = in_plane_axes();
  return point_ + location.coordinates[0] * e1 + location.coordinates[1] * e2;
}

DisplayMesh Plane::display_mesh() const {
  const auto [e1, e2] = in_plane_axes();
  const double h = 0.5 * display_size_m_;
  DisplayMesh mesh;
  mesh.vertices_m = {point_ - h * e1 - h * e2, point_ + h * e1 - h * e2, point_ + h * e1 + h * e2,
                     point_ - h * e1 + h * e2};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

}  // namespace tightfit
