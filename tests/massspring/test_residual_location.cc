// Where a step's residual sits (contact/residual_location.h): the largest residual's vertex,
// its normal and tangential parts to the body, the garment's net force and the rms, against
// values worked out by hand for a plane body.
#include "bodies/plane.h"
#include "contact/residual_location.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tightfit {
namespace {

TEST(ResidualLocation, FindsTheLargestResidualAndSplitsItAlongThePlanesNormal) {
  // The floor z = 0 (outward +z). Vertex 1 holds the largest residual, (3, 0, -4) N: 4 N into
  // the floor, 3 N along it, 5 N in all, at 2 mm above the floor.
  const Plane floor(Vec3::Zero(), Vec3::UnitZ());
  const std::vector<Vec3> x{Vec3(0.1, 0.0, 0.01), Vec3(0.2, 0.3, 0.002), Vec3(-0.1, 0.0, -0.001)};
  const std::vector<Vec3> f{Vec3(1.0, 2.0, 2.0), Vec3(3.0, 0.0, -4.0), Vec3(0.0, 0.0, 0.0)};
  const ResidualLocation where = locate_residual(x, f, &floor);
  EXPECT_EQ(where.vertex, 1);
  EXPECT_NEAR(where.largest_N, 5.0, 1e-12);
  EXPECT_NEAR(where.normal_N, -4.0, 1e-12);
  EXPECT_NEAR(where.tangential_N, 3.0, 1e-12);
  EXPECT_NEAR(where.gap_m, 0.002, 1e-15);
  EXPECT_NEAR((where.position_m - x[1]).norm(), 0.0, 1e-15);
  // Net force (4, 2, -2) N; rms sqrt((9 + 25 + 0) / 3) N.
  EXPECT_NEAR((where.net_force_N - Vec3(4.0, 2.0, -2.0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(where.rms_N, std::sqrt(34.0 / 3.0), 1e-12);
  const std::string line = text(where);
  EXPECT_NE(line.find("vertex 1"), std::string::npos) << line;
  EXPECT_NE(line.find("net force on the garment (4, 2, -2) N"), std::string::npos) << line;
}

TEST(ResidualLocation, WithoutABodyOrVerticesReportsWhatItCan) {
  const std::vector<Vec3> x{Vec3(0.0, 0.0, 1.0)};
  const std::vector<Vec3> f{Vec3(0.0, 2.0, 0.0)};
  const ResidualLocation where = locate_residual(x, f, nullptr);
  EXPECT_EQ(where.vertex, 0);
  EXPECT_NEAR(where.largest_N, 2.0, 1e-15);
  EXPECT_EQ(where.normal_N, 0.0);
  EXPECT_EQ(where.tangential_N, 0.0);
  EXPECT_EQ(locate_residual({}, {}, nullptr).vertex, -1);
  EXPECT_EQ(text(locate_residual({}, {}, nullptr)), "no vertex");
}

}  // namespace
}  // namespace tightfit
