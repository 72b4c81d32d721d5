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

}  // namespace tightfit::testing
