#include "contact/plane.h"

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
  return s;
}

DisplayMesh Plane::display_mesh() const {
  const Vec3 seed = std::abs(normal_.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 e1 = (seed - seed.dot(normal_) * normal_).normalized();
  const Vec3 e2 = normal_.cross(e1);
  const double h = 0.5 * display_size_m_;
  DisplayMesh mesh;
  mesh.vertices_m = {point_ - h * e1 - h * e2, point_ + h * e1 - h * e2, point_ + h * e1 + h * e2,
                     point_ - h * e1 + h * e2};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

}  // namespace tightfit
