// The smooth contact surface of a mesh body (MeshBodyOptions::ContactSurface::smooth,
// bodies/blended_quadric_field.h) on a faceted cylinder: its gap against the true cylinder's,
// its gradient and Hessian against finite differences of its own gap, the work of its contact
// force round a closed loop (zero for a force that derives from an energy), and the surface
// location's round trip.
#include "bodies/mesh_body.h"
#include "contact/penalty_contact.h"
#include "tests/bodies/body_mesh_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace tightfit {
namespace {

using testing::revolution_surface;

constexpr double kRadius = 0.05;
constexpr int kRound =
    24;  // 15 degrees a facet: h = 1.31 cm, sagitta s = R (1 - cos 7.5) = 0.43 mm

MeshBody cylinder_mesh(MeshBodyOptions::ContactSurface kind) {
  std::vector<double> z, r;
  for (int k = 0; k <= 30; ++k) z.push_back(-0.15 + 0.01 * k), r.push_back(kRadius);
  MeshBodyOptions options;
  options.import.up_axis = "+z";
  options.contact_surface = kind;
  return MeshBody(import_surface(revolution_surface(z, r, kRound), options.import), options);
}

// Points round the middle of the cylinder, at angles over two facets (vertex, face, edge) and
// between two rings, from 1 mm inside to 1 mm outside the true cylinder.
std::vector<Vec3> points_near_the_surface() {
  std::vector<Vec3> points;
  for (int a = 0; a <= 16; ++a)
    for (double offset : {-1e-3, -1e-4, 0.0, 1e-4, 1e-3}) {
      const double angle = a * (2 * M_PI / kRound) / 8, rho = kRadius + offset;
      points.emplace_back(rho * std::cos(angle), rho * std::sin(angle), 0.003 + 0.0004 * a);
    }
  return points;
}

TEST(SmoothContactSurface, GapAndNormalOfAFacetedCylinder) {
  const MeshBody smooth = cylinder_mesh(MeshBodyOptions::ContactSurface::smooth);
  const MeshBody faceted = cylinder_mesh(MeshBodyOptions::ContactSurface::faceted);
  double smooth_error = 0, faceted_error = 0, smooth_angle = 0;
  for (const Vec3& x : points_near_the_surface()) {
    const double exact = std::hypot(x.x(), x.y()) - kRadius;
    const SurfacePoint s = smooth.query(x);
    smooth_error = std::max(smooth_error, std::abs(s.signed_distance_m - exact));
    faceted_error = std::max(faceted_error, std::abs(faceted.query(x).signed_distance_m - exact));
    const Vec3 radial = Vec3(x.x(), x.y(), 0).normalized();
    smooth_angle = std::max(smooth_angle, std::acos(std::min(1.0, s.outward_normal.dot(radial))));
  }
  const double sagitta = kRadius * (1 - std::cos(M_PI / kRound));
  std::printf("gap error: smooth %.3g m, faceted %.3g m (sagitta %.3g m); normal within %.3g deg\n",
              smooth_error, faceted_error, sagitta, smooth_angle * 180 / M_PI);
  EXPECT_NEAR(faceted_error, sagitta, 1e-3 * sagitta);  // the faceted gap misses by the sagitta
  EXPECT_LT(smooth_error, 0.1 * sagitta);
  EXPECT_LT(smooth_angle, 1.0 * M_PI / 180);
}

// Central differences of the gap and of the normal (step 1e-7 m: truncation (h/R)^2 ~ 1e-12
// relative, round-off 1e-16 / 1e-7 = 1e-9). The normal is the field's, grad phi / |grad phi|,
// and its derivative (I - n n^T) H / m is exact at any gap (mesh_body_smooth.cc), so it is
// compared at every point, from 1 mm inside to 1 mm outside. Measured within 1e-7 1/m; bound
// 1e-5 1/m against entries of 1 / R = 20 1/m (the derivative that left out the terms of order
// g missed by 0.04 1/m at 0.1 mm).
TEST(SmoothContactSurface, GradientAndNormalDerivativeMatchFiniteDifferences) {
  const MeshBody body = cylinder_mesh(MeshBodyOptions::ContactSurface::smooth);
  const double h = 1e-7;
  double worst_gradient = 0, worst_derivative = 0;
  for (const Vec3& x : points_near_the_surface()) {
    const SurfacePoint s = body.query(x);
    Vec3 gradient;
    Mat3 derivative;
    for (int j = 0; j < 3; ++j) {
      const SurfacePoint plus = body.query(x + h * Vec3::Unit(j)),
                         minus = body.query(x - h * Vec3::Unit(j));
      gradient[j] = (plus.signed_distance_m - minus.signed_distance_m) / (2 * h);
      derivative.col(j) = (plus.outward_normal - minus.outward_normal) / (2 * h);
    }
    worst_gradient = std::max(worst_gradient, (gradient - s.gap_gradient).norm());
    worst_derivative = std::max(worst_derivative, (derivative - s.normal_derivative_per_m).norm());
    // The gradient is the returned normal up to phi H n / m^2 = O(g / R).
    EXPECT_LT((s.gap_gradient - s.outward_normal).norm(),
              2 * std::abs(s.signed_distance_m) / kRadius + 1e-9);
  }
  std::printf("largest difference: gradient %.3g, normal's derivative %.3g 1/m\n", worst_gradient,
              worst_derivative);
  EXPECT_LT(worst_gradient, 1e-7);
  EXPECT_LT(worst_derivative, 1e-5);
}

// The work of the contact force f = lambda n (penalty_contact.h, plain penalty) round a closed
// loop that crosses facet edges at a depth d inside the surface. A force that is minus the
// gradient of psi(g) does none, up to the loop's quadrature (about 1.5e-7 of the integral of
// |f| |dx| here). The smooth surface's normal is the field's, grad phi / |grad phi|, which
// differs from grad g by phi H n / m^2 (mesh_body_smooth.cc): its work is of order d and
// vanishes with the gap the contact rounds close. Measured 1.3e-5 at d = 0.1 mm and 1.3e-6 at
// 10 micrometres; bounds 3e-5 and 0.3 of the deeper loop's. The faceted surface's force along
// the interpolated normals is not such a gradient at any depth: measured 1.2e-2.
TEST(SmoothContactSurface, ContactForceWorkRoundALoopVanishesWithTheGap) {
  auto loop_work = [](const MeshBody& body, double depth_m) {
    const int steps = 4000;
    const double kA = 3e4;  // N/m: the stocking's k A0 = beta Y
    double work = 0, path = 0;
    auto at = [depth_m](int i) {
      // Over the first half of the facet from angle 0 to 15 degrees, where the interpolated
      // normal leans one way (a loop round the vertex at angle 0 would see the leans cancel).
      const double t = 2 * M_PI * i / steps, angle = 0.065 + 0.05 * std::cos(t);
      const double rho = kRadius - depth_m + 0.5 * depth_m * std::sin(t);
      return Vec3(rho * std::cos(angle), rho * std::sin(angle), 0.004 * std::sin(t));
    };
    for (int i = 0; i < steps; ++i) {
      const Vec3 a = at(i), b = at(i + 1), middle = 0.5 * (a + b);
      const Vec3 f = penalty_force_N(body.query(middle), kA, 1.0);
      work += f.dot(b - a);
      path += f.norm() * (b - a).norm();
    }
    return work / path;
  };
  const MeshBody smooth = cylinder_mesh(MeshBodyOptions::ContactSurface::smooth);
  const double smooth_deep = loop_work(smooth, 1e-4), smooth_shallow = loop_work(smooth, 1e-5);
  const double faceted = loop_work(cylinder_mesh(MeshBodyOptions::ContactSurface::faceted), 1e-4);
  std::printf(
      "loop work over the integral of |f| |dx|: smooth %.3g (0.1 mm), %.3g (10 um), faceted "
      "%.3g\n",
      smooth_deep, smooth_shallow, faceted);
  EXPECT_LT(std::abs(smooth_deep), 3e-5);
  EXPECT_LT(std::abs(smooth_shallow), 0.3 * std::abs(smooth_deep));
  EXPECT_GT(std::abs(faceted), 1e-3);
}

// The closest point, its location and the point surface_point_m() finds from that location
// again (friction anchors rely on it), also with a skin offset. The closest point is Newton's
// projection onto the level set, three steps from 1 mm off: measured within 1.6e-10 m of
// where surface_point_m() puts it back (bound 1e-9 m).
TEST(SmoothContactSurface, LocationRoundTrip) {
  for (double skin : {0.0, 0.003}) {
    std::vector<double> z, r;
    for (int k = 0; k <= 30; ++k) z.push_back(-0.15 + 0.01 * k), r.push_back(kRadius);
    MeshBodyOptions options;
    options.import.up_axis = "+z";
    options.skin_offset_m = skin;
    options.contact_surface = MeshBodyOptions::ContactSurface::smooth;
    const MeshBody body(import_surface(revolution_surface(z, r, kRound), options.import), options);
    double worst = 0;
    for (const Vec3& x : points_near_the_surface()) {
      const SurfacePoint s = body.query(x);
      const double off = (body.surface_point_m(s.location) - s.closest_point_m).norm();
      worst = std::max(worst, off);
      EXPECT_LT(off, 1e-9) << "x = " << x.transpose();
      EXPECT_LT(std::abs(body.query(s.closest_point_m).signed_distance_m), 1e-9);
    }
    std::printf("skin %.3g m: round trip within %.3g m\n", skin, worst);
  }
}

// MakeHuman's default female (data/bodies/) with the smooth contact surface.
std::unique_ptr<MeshBody> smooth_female() {
  MeshBodyOptions options;
  options.import.up_axis = "+y";
  options.contact_surface = MeshBodyOptions::ContactSurface::smooth;
  return load_mesh_body(std::string(TIGHTFIT_BODIES_DIR) + "/makehuman_default_female_body_m.obj",
                        options);
}

// On the MakeHuman female's inner left thigh 5.5 cm below the crotch, where the other thigh lies
// within the blend's reach: the gap's central differences along three lines through the point
// (2 cm each, steps of 10 micrometres) match its mean gradient over each step. Measured 1.4e-8
// at most (the midpoint rule's h^2 g''' / 12 where the thigh turns fastest); bound 1e-6. Before
// the facing factor of BlendedQuadricField::evaluate the walk reached the other thigh for some
// points only and the gap jumped (differences of 2.4 against a unit gradient).
TEST(SmoothContactSurface, ContinuousBetweenTheThighs) {
  const auto body = smooth_female();
  const Vec3 x(0.0169, -0.0356, -0.1386);
  const Vec3 n = body->query(x).outward_normal;
  EXPECT_LT(n.x(), -0.5);  // the inner thigh: the surface faces the other leg
  const double h = 1e-5;
  double worst = 0;
  for (const Vec3& e : {Vec3(n.cross(Vec3::UnitZ()).normalized()), Vec3(Vec3::UnitZ()), n}) {
    SurfacePoint before = body->query(x - 0.01 * e);
    for (int k = 1; k <= 2000; ++k) {
      const SurfacePoint after = body->query(x + (k * h - 0.01) * e);
      const double difference = (after.signed_distance_m - before.signed_distance_m) / h;
      const double gradient = 0.5 * (after.gap_gradient + before.gap_gradient).dot(e);
      worst = std::max(worst, std::abs(difference - gradient));
      before = after;
    }
  }
  std::printf("between the thighs: differences within %.3g of the gradient\n", worst);
  EXPECT_LT(worst, 1e-6);
}

// On the MakeHuman female's inner lower leg, where the body's faces are large against the leg's
// radius and the blend holds quadrics turned 90 to 120 degrees from the surface's normal (their
// facing factor between 0 and 1): the gap is C1, its second differences along three lines
// through a point on the surface (2 cm each, steps of 1 micrometre) bounded by the surface's
// curvature and the blend. Measured: at most 261 1/m; bound 400 1/m. With the facing factor
// read from the flat closest point's interpolated normal, whose derivative jumps where that
// point passes from a face onto an edge, the gap has kinks here (its slope along y through a
// nearby vertex of the coarse stocking fell by 0.013 within 2 micrometres) and its second
// differences on these lines reached 1.9e6 1/m.
TEST(SmoothContactSurface, GapIsC1OverTheLowerLeg) {
  const auto body = smooth_female();
  const Vec3 near(0.134, -0.012, -0.633);
  const SurfacePoint at = body->query(near);
  const Vec3 x = at.closest_point_m;
  const double h = 1e-6;
  double worst = 0;
  for (const Vec3& e : {Vec3(Vec3::UnitX()), Vec3(Vec3::UnitY()), Vec3(Vec3::UnitZ())}) {
    double before = body->query(x - 0.01 * e).signed_distance_m;
    double middle = body->query(x + (h - 0.01) * e).signed_distance_m;
    for (int k = 2; k <= 20000; ++k) {
      const double after = body->query(x + (k * h - 0.01) * e).signed_distance_m;
      worst = std::max(worst, std::abs(after - 2 * middle + before) / (h * h));
      before = middle;
      middle = after;
    }
  }
  std::printf("over the lower leg: second differences of the gap within %.3g 1/m\n", worst);
  EXPECT_LT(worst, 400.0);
}

}  // namespace
}  // namespace tightfit
