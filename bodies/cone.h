// A rigid solid circular cone, semi-infinite: from its apex it widens along `axis` without end
// (a limb segment that tapers: the garment only ever touches a band of it). Its distance,
// normal and normal derivative are exact (docs/bodies.md "Body kinds").
#pragma once

#include "bodies/rigid_body.h"

namespace tightfit {

struct ConeOptions {
  Vec3 point_on_axis_m = Vec3::Zero();  // the reference point
  Vec3 axis = Vec3::UnitZ();            // the direction in which the radius grows (any length)
  double half_angle_deg = 10.0;         // between the axis and the surface, in (0, 90)
  double radius_at_point_m = 0.05;      // the radius at the reference point, > 0
  double display_length_m = 0.24;       // how much of it is drawn, centred on the point
};

class Cone final : public RigidBody {
 public:
  // Throws std::invalid_argument for a zero axis, a half-angle outside (0, 90) degrees or a
  // radius that is not positive.
  explicit Cone(const ConeOptions& options);

  std::string name() const override { return "cone"; }
  // The location's coordinates are (axial coordinate of the closest point from the reference
  // point (m), angle round the axis from the reference direction (radians), 0).
  SurfacePoint query(const Vec3& x) const override;
  DisplayMesh display_mesh() const override;
  Vec3 surface_point_m(const SurfaceLocation& location) const override;

  // Scales every distance from the axis by `factor` > 0 relative to the cone as built (the
  // apex stays put; the half-angle becomes atan(factor tan(half-angle))): the cone grows the
  // way the cylinder's radius does.
  void set_radial_scale(double factor);
  double radius_at_m(double axial_coordinate_m) const;  // 0 behind the apex
  double half_angle_rad() const;
  Vec3 apex_m() const;

 private:
  ConeOptions options_;
  Vec3 axis_;               // unit
  double tan_half_angle_;   // current (scaled)
  double radius_at_point_;  // current (scaled)
};

}  // namespace tightfit
