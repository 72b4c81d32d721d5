// The cone's exact distance, normal and surface parameters against values worked out by hand.
#include "bodies/cone.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit {
namespace {

void expect_near(const Vec3& got, const Vec3& want, double tolerance) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tolerance) << "component " << c;
}

// Half-angle 45 degrees, radius 1 at (0, 0, 1) on the z axis: the apex is the origin and the
// surface is rho = z.
ConeOptions right_angled_cone() {
  ConeOptions o;
  o.point_on_axis_m = Vec3(0, 0, 1);
  o.axis = Vec3(0, 0, 2);  // need not be unit
  o.half_angle_deg = 45.0;
  o.radius_at_point_m = 1.0;
  return o;
}

TEST(Cone, OutsideBesideTheSurface) {
  // x = (2, 0, 1): rho = 2, z = 1, so g = (rho - z) cos 45 = 1/sqrt(2), n = (1, 0, -1)/sqrt(2),
  // and the foot x - g n = (1.5, 0, 1.5) lies on rho = z.
  const Cone cone(right_angled_cone());
  const SurfacePoint s = cone.query(Vec3(2, 0, 1));
  EXPECT_NEAR(s.signed_distance_m, 1 / std::sqrt(2.0), 1e-15);
  expect_near(s.outward_normal, Vec3(1, 0, -1) / std::sqrt(2.0), 1e-15);
  expect_near(s.closest_point_m, Vec3(1.5, 0, 1.5), 1e-15);
  expect_near(s.gap_gradient, s.outward_normal, 0.0);
  EXPECT_NEAR(s.location.coordinates[0], 0.5, 1e-15);  // the foot is 0.5 above the point
  EXPECT_NEAR(s.location.coordinates[1], 0.0, 1e-15);  // angle from +x
}

TEST(Cone, InsideOnTheAxis) {
  // (0, 0, 2): the nearest generator is 2 sin 45 = sqrt(2) away.
  const SurfacePoint s = Cone(right_angled_cone()).query(Vec3(0, 0, 2));
  EXPECT_NEAR(s.signed_distance_m, -std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(s.outward_normal.norm(), 1.0, 1e-15);
  EXPECT_NEAR(s.outward_normal.z(), -1 / std::sqrt(2.0), 1e-15);
}

TEST(Cone, BehindTheApexTheApexIsClosest) {
  const Cone cone(right_angled_cone());
  const SurfacePoint s = cone.query(Vec3(0, 0.6, -0.8));
  EXPECT_NEAR(s.signed_distance_m, 1.0, 1e-15);
  expect_near(s.closest_point_m, Vec3::Zero(), 1e-15);
  expect_near(s.outward_normal, Vec3(0, 0.6, -0.8), 1e-15);
  // On the boundary between the two regions, (1, 0, -1): sqrt(2) from the apex, along the
  // generator's normal: both formulas agree.
  EXPECT_NEAR(cone.query(Vec3(1, 0, -1)).signed_distance_m, std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(cone.query(Vec3(1, 0, -1 + 1e-9)).signed_distance_m, std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(cone.query(Vec3(1, 0, -1 - 1e-9)).signed_distance_m, std::sqrt(2.0), 1e-9);
}

TEST(Cone, RadialScaleKeepsTheApexAndScalesTheRadius) {
  Cone cone(right_angled_cone());
  cone.set_radial_scale(2.0);
  expect_near(cone.apex_m(), Vec3::Zero(), 1e-15);
  EXPECT_NEAR(cone.radius_at_m(0.0), 2.0, 1e-15);
  EXPECT_NEAR(cone.half_angle_rad(), std::atan(2.0), 1e-15);
  EXPECT_NEAR(cone.query(Vec3(2, 0, 1)).signed_distance_m, 0.0, 1e-15);
  // A surface location keeps its axial coordinate and angle: the point moves out radially.
  SurfaceLocation l;
  l.coordinates = Vec3(0.5, M_PI / 2, 0);
  expect_near(cone.surface_point_m(l), Vec3(0, 3, 1.5), 1e-15);
  cone.set_radial_scale(1.0);
  expect_near(cone.surface_point_m(l), Vec3(0, 1.5, 1.5), 1e-15);
}

TEST(Cone, LocationReturnsTheClosestPoint) {
  ConeOptions o = right_angled_cone();
  o.axis = Vec3(1, 2, 2);
  o.half_angle_deg = 17.0;
  const Cone cone(o);
  for (const Vec3& x : {Vec3(0.3, -0.2, 1.1), Vec3(-2, 0.5, 0.3), Vec3(0.1, 0.2, -0.4)}) {
    const SurfacePoint s = cone.query(x);
    expect_near(cone.surface_point_m(s.location), s.closest_point_m, 1e-14);
    expect_near(x - s.signed_distance_m * s.outward_normal, s.closest_point_m, 1e-14);
  }
}

TEST(Cone, RejectsBadShapes) {
  ConeOptions o = right_angled_cone();
  o.half_angle_deg = 90.0;
  EXPECT_THROW(Cone{o}, std::invalid_argument);
  o.half_angle_deg = 0.0;
  EXPECT_THROW(Cone{o}, std::invalid_argument);
  o = right_angled_cone();
  o.radius_at_point_m = -0.1;
  EXPECT_THROW(Cone{o}, std::invalid_argument);
  o = right_angled_cone();
  o.axis = Vec3::Zero();
  EXPECT_THROW(Cone{o}, std::invalid_argument);
  EXPECT_THROW(Cone(right_angled_cone()).set_radial_scale(0.0), std::invalid_argument);
}

}  // namespace
}  // namespace tightfit
