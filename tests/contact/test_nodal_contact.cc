// The augmented-Lagrangian contact of one vertex: its stiffness against finite differences of
// its force, and its multiplier against the law of penalty_contact.h.
#include "bodies/cone.h"
#include "bodies/cylinder.h"
#include "bodies/mesh_body.h"
#include "central_difference.h"
#include "contact/nodal_contact.h"
#include "tests/bodies/body_mesh_files.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit {
namespace {

const double penalty = 2e4, multiplier = 0.3;

// -d(force)/dx by central differences (step 1e-7 m). The force is of order 1 N and
// kA = 2e4 N/m: differences of 1e-16 N over 2e-7 m leave 1e-9 N/m of round-off, so 1e-5
// relative to |K| ~ 2e4 is far above it.
Mat3 minus_force_derivative(const RigidBody& body, const Vec3& x) {
  return testing::minus_force_jacobian(
      [&](const Vec3& y) { return nodal_contact(body, y, multiplier, penalty, false).force_N; }, x);
}

TEST(NodalContact, StiffnessIsMinusTheForceDerivative) {
  const Cylinder cylinder(Vec3(0.01, 0, 0), Vec3(1, 1, 3).normalized(), 0.05);
  const Vec3 x(0.04, 0.031, 0.02);  // inside, near the surface
  const NodalContact c = nodal_contact(cylinder, x, multiplier, penalty, true);
  ASSERT_GT(c.multiplier_N, 0.0);
  EXPECT_LT((c.stiffness_N_per_m - minus_force_derivative(cylinder, x)).norm(),
            1e-5 * c.stiffness_N_per_m.norm());
  // The potential's derivative: lambda = max(0, lambda_bar - kA g).
  EXPECT_NEAR(c.multiplier_N, multiplier - penalty * c.gap_m, 1e-12);
  // Outside by more than lambda_bar / kA: no force.
  const Vec3 outside = cylinder.query(x).closest_point_m + 1e-3 * cylinder.query(x).outward_normal;
  EXPECT_EQ(nodal_contact(cylinder, outside, multiplier, penalty, true).multiplier_N, 0.0);
}

// On a cone (symmetric dn/dx) the stiffness is the whole derivative; on a mesh body, whose
// smooth normal differs from the faces' dg/dx, it is the derivative's symmetric part, and the
// exact stiffness the whole derivative.
TEST(NodalContact, StiffnessOnAConeAndAMeshBody) {
  ConeOptions o;
  o.axis = Vec3(0, 1, 1);
  const Cone cone(o);
  const Vec3 in_cone(0.0499, 0.0, 0.0);  // 0.1 mm from the 5 cm radius at the axis point
  EXPECT_LT((nodal_contact(cone, in_cone, multiplier, penalty, true).stiffness_N_per_m -
             minus_force_derivative(cone, in_cone))
                .norm(),
            1e-5 * penalty);

  MeshBodyOptions options;
  options.import.up_axis = "+z";
  const MeshBody body(
      import_surface(testing::revolution_surface({-0.1, 0.0, 0.1}, {0.05, 0.05, 0.05}, 16),
                     options.import),
      options);
  // The facet at angle 0.2 lies 0.05 cos(pi/16) = 0.04904 m from the axis: 0.0485 is 0.5 mm in.
  const Vec3 x(0.0485 * std::cos(0.2), 0.0485 * std::sin(0.2), 0.03);
  const NodalContact c = nodal_contact(body, x, multiplier, penalty, true);
  ASSERT_GT(c.multiplier_N, 0.0);
  const Mat3 K_fd = minus_force_derivative(body, x);
  EXPECT_LT((c.stiffness_N_per_m - 0.5 * (K_fd + K_fd.transpose())).norm(),
            1e-5 * c.stiffness_N_per_m.norm());
  // The unsymmetrised one is the whole derivative, and the multiplier's gradient its own.
  EXPECT_LT((c.exact_stiffness_N_per_m - K_fd).norm(), 1e-5 * c.stiffness_N_per_m.norm());
  EXPECT_GT((c.exact_stiffness_N_per_m - c.stiffness_N_per_m).norm(),
            1e-3 * c.stiffness_N_per_m.norm());
  const double h = 1e-7;
  for (int j = 0; j < 3; ++j) {
    const Vec3 e = h * Vec3::Unit(j);
    const double dlambda = (nodal_contact(body, x + e, multiplier, penalty, false).multiplier_N -
                            nodal_contact(body, x - e, multiplier, penalty, false).multiplier_N) /
                           (2 * h);
    EXPECT_NEAR(c.multiplier_gradient_N_per_m[j], dlambda, 1e-5 * penalty) << "component " << j;
  }
}

}  // namespace
}  // namespace tightfit
