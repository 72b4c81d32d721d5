// Bodies with landmarks known by construction, for the body module's tests: closed triangle
// meshes of elliptic cylinders, spheres and their union (CGAL's corefinement), standing in
// tightfit's frame (z up, front -y, left +x).
#pragma once

#include "bodies/triangle_surface.h"

#include <vector>

namespace tightfit::testing {

// An elliptic cylinder round the line from `base` along the unit `axis` over `length`, semi-axes
// `a` (along `across`, made normal to the axis) and `b`, `n` points round, capped flat at both
// ends; its triangles face outwards.
TriangleSurface elliptic_cylinder(const Vec3& base, const Vec3& axis, const Vec3& across,
                                  double length, double a, double b, int n);
// The same tapering from semi-axes a0, b0 at `base` to a1, b1 at the other end.
TriangleSurface elliptic_frustum(const Vec3& base, const Vec3& axis, const Vec3& across,
                                 double length, double a0, double b0, double a1, double b1, int n);
// A sphere as a UV mesh, its poles on the z axis through `centre`.
TriangleSurface sphere(const Vec3& centre, double radius, int n_around, int n_rings);
// The union of closed surfaces (CGAL::Polygon_mesh_processing::corefine_and_compute_union).
TriangleSurface surface_union(const std::vector<TriangleSurface>& parts);

// A person of cylinders and spheres: legs (radius 0.06 m, axes at x = +-0.09 m) from the floor
// z = 0 into the torso, an elliptic torso (semi-axes 0.16 m across, 0.11 m deep) from the
// crotch z = 0.75 m to z = 1.40 m, a neck and a head (radius 0.1 m, top z = 1.65 m), and arms
// (radius 0.04 m, 0.6 m long) from the shoulder joints (+-0.12, 0, 1.34) m at `arm_angle_deg`
// from the vertical (45: A-pose, 90: T-pose). Without legs when `legs` is false.
struct SyntheticPerson {
  static constexpr double crotch_m = 0.75, top_m = 1.65, torso_a = 0.16, torso_b = 0.11;
  static constexpr double leg_r = 0.06, arm_r = 0.04, joint_x = 0.12, joint_z = 1.34;
  // The armpit: where the arm's underside meets the torso's side (in the plane y = 0).
  static double armpit_z(double arm_angle_deg);
};
TriangleSurface synthetic_person(double arm_angle_deg, bool legs = true);

// The legs as (circular) frusta from the floor z = 0 to z = top_z, their axes tilted
// `tilt_deg` outwards from the vertical in the plane y = 0, passing x = +-top_x at z = top_z;
// radius foot_r at the floor, top_r at the top. The defaults are synthetic_person's cylinders.
struct SyntheticLegs {
  double tilt_deg = 0.0, foot_r = SyntheticPerson::leg_r, top_r = SyntheticPerson::leg_r;
  double top_x = 0.09, top_z = 0.85;
  Vec3 up(int side) const;    // the axis of leg `side` (0 left at +x, 1 right), unit, upwards
  Vec3 foot(int side) const;  // the axis's point at the floor
};
TriangleSurface synthetic_person(double arm_angle_deg, const SyntheticLegs& legs,
                                 bool legs_present = true);

}  // namespace tightfit::testing
