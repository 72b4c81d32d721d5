// A rigid circular cylinder with any axis, whose radius the load steps grow (the paper's
// Section 4.3: the cylinder is scaled radially once the garment has settled).
#pragma once

#include "bodies/rigid_body.h"

namespace tightfit {

class Cylinder final : public RigidBody {
 public:
  // Infinite for contact; `display_height_m` only sets how much of it is drawn.
  Cylinder(const Vec3& point_on_axis_m, const Vec3& axis, double radius_m,
           double display_height_m = 0.24);

  std::string name() const override { return "cylinder"; }
  // The location's coordinates are (axial coordinate from point_on_axis_m (m), angle round the
  // axis from reference_direction() (radians), 0): the same point as the radius grows.
  SurfacePoint query(const Vec3& x) const override { return answer(x, QueryParts{}); }
  SurfacePoint query_parts(const Vec3& x, NearFaces&, QueryParts parts) const override {
    return answer(x, parts);
  }
  DisplayMesh display_mesh() const override;
  Vec3 surface_point_m(const SurfaceLocation& location) const override;

  void set_radius(double radius_m);  // throws std::invalid_argument unless positive
  double radius_m() const { return radius_m_; }
  const Vec3& axis() const { return axis_; }
  const Vec3& point_on_axis_m() const { return point_; }
  // Unit vector normal to the axis from which angles round the cylinder are measured.
  Vec3 reference_direction() const;
  // Angle of x round the axis from reference_direction(), degrees in [0, 360).
  double angle_deg(const Vec3& x) const;

 private:
  SurfacePoint answer(const Vec3& x, QueryParts parts) const;

  Vec3 point_;
  Vec3 axis_;
  // The frame the angles are measured in: reference_direction(), axis x it, and the projection
  // I - a a^T normal to the axis, kept so that a query does not build them again.
  Vec3 e1_, e2_;
  Mat3 across_axis_;
  double radius_m_;
  double display_height_m_;
};

}  // namespace tightfit
