// The augmented-Lagrangian contact of one vertex: its stiffness against finite differences of
// its force, and its multiplier against the law of penalty_contact.h.
#include "contact/cylinder.h"
#include "contact/nodal_contact.h"

#include <gtest/gtest.h>

namespace tightfit {
namespace {

TEST(NodalContact, StiffnessIsMinusTheForceDerivative) {
  const Cylinder cylinder(Vec3(0.01, 0, 0), Vec3(1, 1, 3).normalized(), 0.05);
  const double penalty = 2e4, multiplier = 0.3;
  const Vec3 x(0.04, 0.031, 0.02);  // inside, near the surface
  const NodalContact c = nodal_contact(cylinder, x, multiplier, penalty, true);
  ASSERT_GT(c.multiplier_N, 0.0);
  const double h = 1e-7;
  Mat3 K_fd;
  for (int j = 0; j < 3; ++j) {
    const Vec3 e = h * Vec3::Unit(j);
    K_fd.col(j) = -(nodal_contact(cylinder, x + e, multiplier, penalty, false).force_N -
                    nodal_contact(cylinder, x - e, multiplier, penalty, false).force_N) /
                  (2 * h);
  }
  EXPECT_LT((c.stiffness_N_per_m - K_fd).norm(), 1e-5 * c.stiffness_N_per_m.norm());
  // The potential's derivative: lambda = max(0, lambda_bar - kA g).
  EXPECT_NEAR(c.multiplier_N, multiplier - penalty * c.gap_m, 1e-12);
  // Outside by more than lambda_bar / kA: no force.
  const Vec3 outside = cylinder.query(x).closest_point_m + 1e-3 * cylinder.query(x).outward_normal;
  EXPECT_EQ(nodal_contact(cylinder, outside, multiplier, penalty, true).multiplier_N, 0.0);
}

}  // namespace
}  // namespace tightfit
