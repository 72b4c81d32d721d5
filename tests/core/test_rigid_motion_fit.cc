// fit_rigid_motion against fields whose rigid part is known in closed form: a rigid motion
// (all of it), a radial expansion of a symmetric tube (none of it: orthogonal to every rigid
// motion), and their sum (the shares of the two orthogonal parts).
#include "core/rigid_motion_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace tightfit {
namespace {

// A tube of 24 x 5 points round an oblique axis through `centre`: its centroid is `centre`, and
// the radial field r - ((r . a) a) sums to zero with zero moment about it.
struct Tube {
  Vec3 centre{0.1, -0.2, 0.3};
  Vec3 axis = Vec3(1, 2, 3).normalized();
  std::vector<Vec3> points, radial;
  Tube() {
    const Vec3 u = axis.unitOrthogonal(), v = axis.cross(u);
    for (int k = 0; k < 5; ++k)
      for (int j = 0; j < 24; ++j) {
        const double phi = 2 * M_PI * j / 24, h = 0.05 * (k - 2);
        const Vec3 out = 0.06 * (std::cos(phi) * u + std::sin(phi) * v);
        points.push_back(centre + h * axis + out);
        radial.push_back(out);
      }
  }
};

TEST(RigidMotionFit, RecoversARigidMotionWhole) {
  const Tube tube;
  const Vec3 w(0.002, -0.001, 0.004), t(1e-4, 2e-4, -3e-4), pivot(0.5, 0.5, 0.5);
  std::vector<Vec3> d;
  for (const Vec3& p : tube.points) d.push_back(t + w.cross(p - pivot));
  const RigidMotionFit fit = fit_rigid_motion(tube.points, d);
  // Exact up to round-off: the field is rigid.
  EXPECT_NEAR(fit.explained, 1.0, 1e-12);
  EXPECT_LT((fit.rotation_rad - w).norm(), 1e-12);
  // About the centroid the translation absorbs the pivot's offset.
  EXPECT_LT((fit.translation_m - (t + w.cross(tube.centre - pivot))).norm(), 1e-12);
  EXPECT_LT((fit.centre_m - tube.centre).norm(), 1e-12);
}

TEST(RigidMotionFit, FindsNoRigidPartInARadialExpansion) {
  const Tube tube;
  std::vector<Vec3> d;
  for (const Vec3& r : tube.radial) d.push_back(1e-3 * r);
  EXPECT_LT(fit_rigid_motion(tube.points, d).explained, 1e-12);
}

TEST(RigidMotionFit, SharesASumOfOrthogonalParts) {
  const Tube tube;
  // A turn about the tube's own axis (3 mm at its radius) plus a radial expansion of 1 mm.
  const Vec3 w = 0.05 * tube.axis;
  std::vector<Vec3> d;
  double rigid = 0, radial = 0;
  for (std::size_t i = 0; i < tube.points.size(); ++i) {
    const Vec3 turn = w.cross(tube.points[i] - tube.centre), grow = (1e-3 / 0.06) * tube.radial[i];
    d.push_back(turn + grow);
    rigid += turn.squaredNorm();
    radial += grow.squaredNorm();
  }
  const RigidMotionFit fit = fit_rigid_motion(tube.points, d);
  EXPECT_NEAR(fit.explained, rigid / (rigid + radial), 1e-12);
  EXPECT_LT((fit.rotation_rad - w).norm(), 1e-12);
  EXPECT_NE(text(fit).find("90% a rigid motion"), std::string::npos) << text(fit);
}

TEST(RigidMotionFit, RefusesMismatchedSizes) {
  EXPECT_THROW(fit_rigid_motion({Vec3::Zero()}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace tightfit
