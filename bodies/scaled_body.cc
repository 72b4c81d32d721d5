#include "bodies/scaled_body.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace tightfit {

ScaledBody::ScaledBody(const RigidBody& body, const Vec3& centre_m)
    : body_(body), centre_m_(centre_m) {
  find_reach();
}

ScaledBody::ScaledBody(const RigidBody& body, const Vec3& centre_m, const Vec3& axis)
    : body_(body), centre_m_(centre_m) {
  if (!(axis.norm() > 0)) throw std::invalid_argument("a scaling axis must not be zero");
  const Vec3 a = axis.normalized();
  along_ = a * a.transpose();
  find_reach();
}

void ScaledBody::find_reach() {
  for (const Vec3& p : body_.display_mesh().vertices_m) {
    const Vec3 d = p - centre_m_;
    reach_m_ = std::max(reach_m_, Vec3(d - along_ * d).norm());
  }
}

void ScaledBody::set_scale(double scale) {
  if (!(scale > 0)) throw std::invalid_argument("a body's scale must be positive");
  scale_ = scale;
}

Vec3 ScaledBody::scaled(const Vec3& y) const {
  const Vec3 d = y - centre_m_;
  const Vec3 axial = along_ * d;
  return centre_m_ + axial + scale_ * (d - axial);
}

Vec3 ScaledBody::unscaled(const Vec3& x) const {
  const Vec3 d = x - centre_m_;
  const Vec3 axial = along_ * d;
  return centre_m_ + axial + (d - axial) / scale_;
}

SurfacePoint ScaledBody::carried(SurfacePoint s) const {
  const auto carried_normal = [&](const Vec3& n) {  // T^-T n
    const Vec3 n_axial = along_ * n;
    return Vec3(n_axial + (n - n_axial) / scale_);
  };
  const Vec3 m = carried_normal(s.outward_normal);
  s.signed_distance_m /= m.norm();
  s.outward_normal = m.normalized();
  s.gap_gradient = carried_normal(s.gap_gradient).normalized();
  s.closest_point_m = scaled(s.closest_point_m);
  s.normal_derivative_per_m /= scale_;
  return s;
}

SurfacePoint ScaledBody::query(const Vec3& x) const {
  return carried(body_.query(unscaled(x)));
}

SurfacePoint ScaledBody::query_near(const Vec3& x, NearFaces& near) const {
  return carried(body_.query_near(unscaled(x), near));
}

SurfacePoint ScaledBody::query_parts(const Vec3& x, NearFaces& near, QueryParts parts) const {
  return carried(body_.query_parts(unscaled(x), near, parts));
}

DisplayMesh ScaledBody::display_mesh() const {
  DisplayMesh mesh = body_.display_mesh();
  for (Vec3& v : mesh.vertices_m) v = scaled(v);
  return mesh;
}

Vec3 ScaledBody::surface_point_m(const SurfaceLocation& location) const {
  return scaled(body_.surface_point_m(location));
}

}  // namespace tightfit
