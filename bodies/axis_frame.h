// Directions round an axis, shared by the bodies of revolution (cylinder, cone).
#pragma once

#include "bodies/rigid_body.h"
#include "core/types.h"

#include <cmath>

namespace tightfit {

// The unit vector normal to the unit axis `a` nearest to +x (or +y when the axis is along x):
// angles round the axis are measured from it.
inline Vec3 reference_direction_normal_to(const Vec3& a) {
  const Vec3 seed = std::abs(a.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (seed - seed.dot(a) * a).normalized();
}

// Angle of `d` round the unit axis `a` from reference_direction_normal_to(a), radians in
// (-pi, pi].
inline double angle_round_axis_rad(const Vec3& a, const Vec3& d) {
  const Vec3 e1 = reference_direction_normal_to(a);
  return std::atan2(d.dot(a.cross(e1)), d.dot(e1));
}

// The unit radial direction at `angle_rad` round the unit axis `a`.
inline Vec3 radial_direction(const Vec3& a, double angle_rad) {
  const Vec3 e1 = reference_direction_normal_to(a);
  return std::cos(angle_rad) * e1 + std::sin(angle_rad) * a.cross(e1);
}

// The drawing of a body of revolution whose SurfaceLocation coordinates are (axial coordinate,
// angle): 22 round by 5 along over `length_m` centred on the axial origin (the paper's
// cylinder had 110 vertices, Table 3).
DisplayMesh revolution_display_mesh(const RigidBody& body, double length_m);

}  // namespace tightfit
