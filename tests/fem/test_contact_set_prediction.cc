// The step's model of a node that the Newton step carries into contact: the unclipped penalty
// force and its tangent against central finite differences, on both sides of the surface.
#include "central_difference.h"
#include "contact/cylinder.h"
#include "contact/nodal_contact.h"
#include "fem/contact_set_prediction.h"

#include <gtest/gtest.h>

namespace tightfit {
namespace {

const double penalty = 2e4, multiplier = 0.3;

// -d(force)/dx of the unclipped force by central differences (step 1e-7 m; as in
// tests/contact/test_nodal_contact.cc, round-off stays near 1e-9 N/m against |K| ~ 2e4 N/m).
Mat3 minus_force_derivative(const RigidBody& body, const Vec3& x) {
  return testing::minus_force_jacobian(
      [&](const Vec3& y) { return unclipped_contact(body, y, multiplier, penalty).force_N; }, x);
}

TEST(ContactSetPrediction, UnclippedForceOutsideTheBodyPullsAndItsTangentIsExact) {
  const Cylinder cylinder(Vec3(0.01, 0, 0), Vec3(1, 1, 3).normalized(), 0.05);
  const SurfacePoint s = cylinder.query(Vec3(0.04, 0.031, 0.02));
  // 2 mm outside: lambda = 0.3 - 2e4 * 0.002 = -39.7 N, a pull towards the body.
  const Vec3 outside = s.closest_point_m + 2e-3 * s.outward_normal;
  const NodalContact c = unclipped_contact(cylinder, outside, multiplier, penalty);
  EXPECT_NEAR(c.multiplier_N, multiplier - penalty * 2e-3, 1e-9);
  EXPECT_LT(c.force_N.dot(s.outward_normal), 0.0);
  const Mat3 K_fd = minus_force_derivative(cylinder, outside);
  EXPECT_LT((c.exact_stiffness_N_per_m - K_fd).norm(), 1e-5 * penalty);
  EXPECT_LT((c.stiffness_N_per_m - 0.5 * (K_fd + K_fd.transpose())).norm(), 1e-5 * penalty);
}

TEST(ContactSetPrediction, UnclippedForceInContactIsTheNodalContact) {
  const Cylinder cylinder(Vec3(0.01, 0, 0), Vec3(1, 1, 3).normalized(), 0.05);
  const Vec3 inside(0.04, 0.031, 0.02);
  const NodalContact u = unclipped_contact(cylinder, inside, multiplier, penalty);
  const NodalContact c = nodal_contact(cylinder, inside, multiplier, penalty, true);
  ASSERT_GT(c.multiplier_N, 0.0);
  EXPECT_LT((u.force_N - c.force_N).norm(), 1e-12);
  EXPECT_LT((u.exact_stiffness_N_per_m - c.exact_stiffness_N_per_m).norm(), 1e-9);
  EXPECT_LT((u.exact_stiffness_N_per_m - minus_force_derivative(cylinder, inside)).norm(),
            1e-5 * penalty);
}

}  // namespace
}  // namespace tightfit
