// Cylinder and plane queries against values worked out by hand.
#include "bodies/cylinder.h"
#include "bodies/plane.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>

namespace tightfit {
namespace {

void expect_near(const Vec3& got, const Vec3& want, double tolerance) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tolerance) << "component " << c;
}

// An oblique axis along (1, 2, 2) (length 3) through p0, and a direction e = (2, -1, 0)/sqrt(5)
// normal to it (1*2 + 2*(-1) + 2*0 = 0): a point p0 + s a + d e lies a distance d from the axis.
struct ObliqueCylinder : ::testing::Test {
  const Vec3 p0{0.1, -0.2, 0.3};
  const Vec3 a = Vec3(1, 2, 2) / 3.0;
  const Vec3 e = Vec3(2, -1, 0) / std::sqrt(5.0);
  const Cylinder cylinder{p0, Vec3(1, 2, 2), 0.05};  // the axis need not be unit
};

TEST_F(ObliqueCylinder, PointOutside) {
  const Vec3 x = p0 + 0.3 * a + 0.08 * e;
  const SurfacePoint s = cylinder.query(x);
  EXPECT_NEAR(s.signed_distance_m, 0.03, 1e-14);
  expect_near(s.closest_point_m, p0 + 0.3 * a + 0.05 * e, 1e-14);
  expect_near(s.outward_normal, e, 1e-14);
}

TEST_F(ObliqueCylinder, PointInside) {
  const Vec3 x = p0 - 1.7 * a - 0.02 * e;
  const SurfacePoint s = cylinder.query(x);
  EXPECT_NEAR(s.signed_distance_m, -0.03, 1e-14);
  expect_near(s.closest_point_m, p0 - 1.7 * a - 0.05 * e, 1e-14);
  // The radial part is found by cancelling 1.7 m along the axis: round-off relative to that.
  expect_near(s.outward_normal, -e, 1e-12);
}

TEST_F(ObliqueCylinder, NumericValuesWorkedOutByHand) {
  // x - p0 = (1.2, 1.9, 2.0), whose component along a is 9/3 = 3: the foot on the axis is
  // p0 + 3 a = (1.1, 1.8, 2.3), and the radial part (0.2, -0.1, 0) has length 0.1 sqrt(5).
  const SurfacePoint s = cylinder.query(Vec3(1.3, 1.7, 2.3));
  EXPECT_NEAR(s.signed_distance_m, 0.22360679774997896 - 0.05, 1e-14);
  // Closest point: foot on the axis (1.1, 1.8, 2.3) plus 0.05 e.
  expect_near(s.closest_point_m, Vec3(1.1 + 0.1 / std::sqrt(5.0), 1.8 - 0.05 / std::sqrt(5.0), 2.3),
              1e-14);
  expect_near(s.outward_normal, Vec3(0.8944271909999159, -0.4472135954999579, 0.0), 1e-14);
}

TEST_F(ObliqueCylinder, PointOnTheAxisGetsAUnitNormalAcrossIt) {
  const SurfacePoint s = cylinder.query(p0 + 2.0 * a);
  EXPECT_NEAR(s.signed_distance_m, -0.05, 1e-14);
  EXPECT_NEAR(s.outward_normal.norm(), 1.0, 1e-14);
  EXPECT_NEAR(s.outward_normal.dot(a), 0.0, 1e-14);
}

TEST_F(ObliqueCylinder, GrowingTheRadiusMovesTheSurface) {
  Cylinder grown = cylinder;
  grown.set_radius(0.09);
  EXPECT_NEAR(grown.query(p0 + 0.08 * e).signed_distance_m, -0.01, 1e-14);
  EXPECT_THROW(grown.set_radius(0.0), std::invalid_argument);
  EXPECT_THROW(grown.set_radius(-1.0), std::invalid_argument);
  EXPECT_THROW(Cylinder(p0, Vec3::Zero(), 0.05), std::invalid_argument);
}

TEST_F(ObliqueCylinder, DisplayMeshLiesOnTheSurface) {
  const DisplayMesh mesh = cylinder.display_mesh();
  EXPECT_EQ(mesh.vertices_m.size(), 110u);  // the paper's Table 3
  for (const Vec3& v : mesh.vertices_m) {
    const Vec3 d = v - p0;
    EXPECT_NEAR((d - d.dot(a) * a).norm(), 0.05, 1e-14);
  }
  for (const Triangle& t : mesh.triangles)
    for (int v : t) EXPECT_LT(v, 110);
}

TEST(CylinderAngle, MeasuredRoundTheAxisFromTheReferenceDirection) {
  const Cylinder cylinder(Vec3(1, 1, 0), Vec3::UnitZ(), 0.05);
  expect_near(cylinder.reference_direction(), Vec3::UnitX(), 1e-15);
  EXPECT_NEAR(cylinder.angle_deg(Vec3(2, 1, 5)), 0.0, 1e-12);
  EXPECT_NEAR(cylinder.angle_deg(Vec3(1, 2, -3)), 90.0, 1e-12);
  EXPECT_NEAR(cylinder.angle_deg(Vec3(0, 1, 0)), 180.0, 1e-12);
  EXPECT_NEAR(cylinder.angle_deg(Vec3(1, 0, 0)), 270.0, 1e-12);
  EXPECT_NEAR(cylinder.angle_deg(Vec3(1 + std::sqrt(3.0), 2, 0)), 30.0, 1e-12);
}

TEST(Plane, QueryAgainstHandComputedValues) {
  // Normal (0, 3, 4)/5 = (0, 0.6, 0.8) through (0, 0, 0.1): x = (1, 2, 3) is
  // 2*0.6 + 2.9*0.8 = 3.52 above it, and its foot is x - 3.52 n = (1, -0.112, 0.184).
  const Plane plane(Vec3(0, 0, 0.1), Vec3(0, 3, 4));
  const SurfacePoint s = plane.query(Vec3(1, 2, 3));
  EXPECT_NEAR(s.signed_distance_m, 3.52, 1e-14);
  expect_near(s.closest_point_m, Vec3(1, -0.112, 0.184), 1e-14);
  expect_near(s.outward_normal, Vec3(0, 0.6, 0.8), 1e-15);

  const SurfacePoint below = plane.query(Vec3(-4, 0, 0));  // 0.1*0.8 = 0.08 under the plane
  EXPECT_NEAR(below.signed_distance_m, -0.08, 1e-15);
  expect_near(below.closest_point_m, Vec3(-4, 0.048, 0.064), 1e-15);
  EXPECT_THROW(Plane(Vec3::Zero(), Vec3::Zero()), std::invalid_argument);
}

}  // namespace
}  // namespace tightfit
