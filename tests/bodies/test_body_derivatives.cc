// Every body kind's normal derivative dn/dx and gap gradient dg/dx against central finite
// differences of its own query().
#include "bodies/cone.h"
#include "bodies/cylinder.h"
#include "bodies/mesh_body.h"
#include "bodies/morphing_mesh_body.h"
#include "bodies/plane.h"
#include "body_mesh_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tightfit {
namespace {

using testing::revolution_surface;

struct Differences {
  Mat3 normal_derivative;
  Vec3 gap_gradient;
};

// Central differences with step h: truncation error h^2 |d3n| / 6, round-off 1e-16 / h.
Differences central_differences(const RigidBody& body, const Vec3& x, double h) {
  Differences d;
  for (int j = 0; j < 3; ++j) {
    const SurfacePoint plus = body.query(x + h * Vec3::Unit(j)),
                       minus = body.query(x - h * Vec3::Unit(j));
    d.normal_derivative.col(j) = (plus.outward_normal - minus.outward_normal) / (2 * h);
    d.gap_gradient[j] = (plus.signed_distance_m - minus.signed_distance_m) / (2 * h);
  }
  return d;
}

// The step is 1e-6 of the body's size (curvature radii of 0.05 m and more, facets of 1 cm):
// the truncation error is then about (h/R)^2 ~ 1e-9 relative, the round-off 1e-10 / h ~ 1e-5 of
// a 1/R ~ 20 entry at most; 1e-5 absolute (1/m) covers both with a margin.
void expect_derivatives_match(const RigidBody& body, const Vec3& x, const char* where) {
  const SurfacePoint s = body.query(x);
  const Differences fd = central_differences(body, x, 1e-7);
  EXPECT_LT((s.normal_derivative_per_m - fd.normal_derivative).norm(), 1e-5)
      << where << "\nexact\n"
      << s.normal_derivative_per_m << "\nfd\n"
      << fd.normal_derivative;
  EXPECT_LT((s.gap_gradient - fd.gap_gradient).norm(), 1e-6) << where;
}

TEST(BodyDerivatives, Plane) {
  const Plane plane(Vec3(0, 0, 0.1), Vec3(0, 3, 4));
  expect_derivatives_match(plane, Vec3(0.2, -0.1, 0.3), "plane, above");
  expect_derivatives_match(plane, Vec3(0.2, -0.1, -0.3), "plane, below");
}

TEST(BodyDerivatives, Cylinder) {
  const Cylinder cylinder(Vec3(0.01, 0, 0), Vec3(1, 1, 3), 0.05);
  expect_derivatives_match(cylinder, Vec3(0.04, 0.031, 0.02), "cylinder, inside");
  expect_derivatives_match(cylinder, Vec3(0.09, -0.031, 0.02), "cylinder, outside");
  // Not zero: the test would pass for a body that ignored its curvature otherwise.
  EXPECT_GT(cylinder.query(Vec3(0.04, 0.031, 0.02)).normal_derivative_per_m.norm(), 10.0);
}

TEST(BodyDerivatives, Cone) {
  ConeOptions o;
  o.point_on_axis_m = Vec3(0.01, 0.02, 0.0);
  o.axis = Vec3(-1, 2, 5);
  o.half_angle_deg = 12.0;
  o.radius_at_point_m = 0.06;
  const Cone cone(o);
  expect_derivatives_match(cone, Vec3(0.05, 0.04, 0.03), "cone, inside");
  expect_derivatives_match(cone, Vec3(0.1, -0.04, 0.05), "cone, outside");
  // Behind the apex (0.28 m down the axis), the apex is the closest point.
  const Vec3 behind = cone.apex_m() - 0.05 * o.axis.normalized() + Vec3(0.01, 0, 0);
  EXPECT_LT((cone.query(behind).closest_point_m - cone.apex_m()).norm(), 1e-15);
  expect_derivatives_match(cone, behind, "cone, behind the apex");
}

// A faceted cylinder of radius 5 cm, 16 facets round, capped, with the closest point of each
// query inside a facet, on an edge between facets, or at a vertex of the rim.
struct MeshDerivatives : ::testing::Test {
  PolygonMesh file = revolution_surface({-0.1, 0.0, 0.1}, {0.05, 0.05, 0.05}, 16);
  TriangleSurface surface() const { return import_surface(file, up_z()); }
  static MeshImportOptions up_z() {
    MeshImportOptions o;
    o.up_axis = "+z";
    return o;
  }
  // Points round vertex 16 (angle 0, z = 0) and the rim vertex 32 (angle 0, z = 0.1).
  const Vec3 face_point{0.052 * std::cos(0.2), 0.052 * std::sin(0.2), 0.03};
  const Vec3 edge_point{0.053, 0.0, 0.04};  // over the edge at angle 0 (convex)
  // Beyond the rim corner at angle 0, within its normals' cone (azimuth 6 < 11.25 degrees).
  const Vec3 vertex_point{0.053, 0.0003, 0.103};
  const Vec3 inside_point{0.045 * std::cos(0.2), 0.045 * std::sin(0.2), -0.03};
};

TEST_F(MeshDerivatives, FaceEdgeAndVertexRegions) {
  MeshBodyOptions options;
  options.import = up_z();
  const MeshBody body(surface(), options);
  for (const auto& [x, where] :
       {std::pair{face_point, "face"}, std::pair{edge_point, "edge"},
        std::pair{vertex_point, "vertex"}, std::pair{inside_point, "inside"}})
    expect_derivatives_match(body, x, where);
  // Each region is what it claims: the closest point is inside a face, on the edge at angle 0,
  // at the rim vertex.
  EXPECT_GT(body.query(face_point).location.coordinates.minCoeff(), 1e-3);
  EXPECT_NEAR(body.query(edge_point).closest_point_m.y(), 0.0, 1e-15);
  EXPECT_LT((body.query(vertex_point).closest_point_m - Vec3(0.05, 0, 0.1)).norm(), 1e-15);
  // The interpolated normal turns inside a face: its derivative is not zero there.
  EXPECT_GT(body.query(face_point).normal_derivative_per_m.norm(), 1.0);
}

TEST_F(MeshDerivatives, WithASkinOffset) {
  MeshBodyOptions options;
  options.import = up_z();
  options.skin_offset_m = 0.004;
  const MeshBody body(surface(), options);
  expect_derivatives_match(body, face_point, "face, skin");
  expect_derivatives_match(body, edge_point, "edge, skin");
}

TEST_F(MeshDerivatives, AfterAMorph) {
  MeshBodyOptions options;
  options.import = up_z();
  BodyScaling scaling;  // about the z axis
  MorphingMeshBody body(surface(), {}, options, scaling);
  body.set_morph(0.0, 1.1);
  expect_derivatives_match(body, face_point * 1.1, "face, scaled");
}

}  // namespace
}  // namespace tightfit
