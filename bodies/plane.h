// A rigid half-space bounded by a plane (a floor, a table).
#pragma once

#include "bodies/rigid_body.h"

#include <utility>

namespace tightfit {

class Plane final : public RigidBody {
 public:
  // The body is the side opposite to `outward_normal`.
  Plane(const Vec3& point_m, const Vec3& outward_normal, double display_size_m = 0.5);
  std::string name() const override { return "plane"; }
  // The location's coordinates are the closest point's (u, v, 0) along in_plane_axes().
  SurfacePoint query(const Vec3& x) const override;
  DisplayMesh display_mesh() const override;
  Vec3 surface_point_m(const SurfaceLocation& location) const override;
  // Two unit vectors along the plane, (e1, e2, normal) right-handed.
  std::pair<Vec3, Vec3> in_plane_axes() const;

 private:
  Vec3 point_;
  Vec3 normal_;
  double display_size_m_;
};

}  // namespace tightfit
