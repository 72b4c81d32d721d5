// The penalty law: no force outside the body, k A0 d along the normal inside.
#include "bodies/plane.h"
#include "contact/penalty_contact.h"

#include <gtest/gtest.h>

namespace tightfit {
namespace {

TEST(PenaltyContact, StiffnessScalesWithTheSquareOfTheEdge) {
  // beta Y / h^2 = 2 * 100 N/m / (0.01 m)^2 = 2e6 Pa/m.
  EXPECT_DOUBLE_EQ(penalty_stiffness_Pa_per_m(2.0, 100.0, 0.01), 2e6);
}

TEST(PenaltyContact, ForceOnlyInside) {
  SurfacePoint s;
  s.outward_normal = Vec3(0, 0.6, 0.8);
  s.signed_distance_m = 1e-3;
  EXPECT_EQ(penalty_force_N(s, 1e5, 1e-4), Vec3::Zero());
  s.signed_distance_m = 0.0;
  EXPECT_EQ(penalty_force_N(s, 1e5, 1e-4), Vec3::Zero());
  // 2 mm deep: 1e5 Pa/m * 1e-4 m^2 * 2e-3 m = 0.02 N out along the normal.
  s.signed_distance_m = -2e-3;
  const Vec3 f = penalty_force_N(s, 1e5, 1e-4);
  EXPECT_NEAR(f.x(), 0.0, 1e-18);
  EXPECT_NEAR(f.y(), 0.012, 1e-15);
  EXPECT_NEAR(f.z(), 0.016, 1e-15);
}

TEST(PenaltyContact, FillsForcesFlagsAndGapsOfEveryVertex) {
  const Plane floor(Vec3::Zero(), Vec3::UnitZ());
  SurfaceState state;
  state.positions_m = {{0, 0, 0.01}, {1, 0, -0.001}, {0, 1, -0.003}};
  apply_penalty_contact(floor, 1e4, {2e-4, 3e-4, 5e-4}, state);
  EXPECT_EQ(state.in_contact, (std::vector<char>{0, 1, 1}));
  EXPECT_NEAR(state.gap_m[0], 0.01, 1e-15);
  EXPECT_NEAR(state.gap_m[1], -0.001, 1e-15);
  EXPECT_NEAR(state.gap_m[2], -0.003, 1e-15);
  EXPECT_EQ(state.contact_force_N[0], Vec3::Zero());
  EXPECT_NEAR(state.contact_force_N[1].z(), 1e4 * 3e-4 * 0.001, 1e-15);  // 3e-3 N
  EXPECT_NEAR(state.contact_force_N[2].z(), 1e4 * 5e-4 * 0.003, 1e-15);  // 1.5e-2 N
  EXPECT_EQ(state.contact_force_N[2].head<2>(), Eigen::Vector2d::Zero());
}

}  // namespace
}  // namespace tightfit
