// Coulomb friction: sticking below mu N, slipping at exactly mu N against the slip, the
// consistent tangent against finite differences, and anchors that a growing or morphing body
// carries with it.
#include "bodies/cylinder.h"
#include "bodies/mesh_body.h"
#include "bodies/morphing_mesh_body.h"
#include "bodies/plane.h"
#include "central_difference.h"
#include "contact/coulomb_friction.h"
#include "tests/bodies/body_mesh_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tightfit {
namespace {

void expect_near(const Vec3& got, const Vec3& want, double tolerance) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tolerance) << "component " << c;
}

CoulombFrictionLaw law(double mu, double k_t) {
  CoulombFrictionLaw l;
  l.friction_coefficient = mu;
  l.tangential_penalty_N_per_m = k_t;
  return l;
}

// The floor z = 0, anchored at the origin, 1 N pressing the vertex onto it.
struct Floor : ::testing::Test {
  const Plane floor{Vec3::Zero(), Vec3::UnitZ()};
  const SurfaceLocation origin = floor.query(Vec3(0, 0, 1)).location;
  FrictionResponse at(const Vec3& x, const CoulombFrictionLaw& l) const {
    return coulomb_friction(floor, x, floor.query(x), 1.0, Vec3::Zero(), origin, l);
  }
};

TEST_F(Floor, SticksBelowMuN) {
  // 1 mm along x at k_t = 100 N/m: 0.1 N < mu N = 0.3 N. The depth (0.1 mm) is normal: no part
  // of the tangential force.
  const FrictionResponse r = at(Vec3(0.001, 0, -1e-4), law(0.3, 100));
  EXPECT_FALSE(r.slipping);
  expect_near(r.force_N, Vec3(-0.1, 0, 0), 1e-15);
  EXPECT_EQ(r.anchor.coordinates, origin.coordinates);
}

TEST_F(Floor, SlipsAtExactlyMuNAgainstTheSlip) {
  // 1 mm along (3, 4, 0)/5 at k_t = 1000 N/m: a 1 N trial force, above mu N = 0.3 N.
  const Vec3 slip_direction(0.6, 0.8, 0.0);
  const Vec3 x = 0.001 * slip_direction + Vec3(0, 0, -2e-4);
  const FrictionResponse r = at(x, law(0.3, 1000));
  EXPECT_TRUE(r.slipping);
  expect_near(r.force_N, -0.3 * slip_direction, 1e-15);
  // The anchor slid to 0.3 / 1000 m behind the vertex along the slip.
  expect_near(floor.surface_point_m(r.anchor), (0.001 - 0.0003) * slip_direction, 1e-15);
  // From the new anchor the same position sits on the cone's edge: still mu N.
  const FrictionResponse again =
      coulomb_friction(floor, x, floor.query(x), 1.0, Vec3::Zero(), r.anchor, law(0.3, 1000));
  EXPECT_NEAR(again.force_N.norm(), 0.3, 1e-12);
}

TEST_F(Floor, NoContactNoFrictionAndTheAnchorResets) {
  const Vec3 x(0.01, 0.02, 0.003);
  const FrictionResponse r =
      coulomb_friction(floor, x, floor.query(x), 0.0, Vec3::Zero(), origin, law(0.3, 1000));
  EXPECT_EQ(r.force_N, Vec3::Zero());
  expect_near(floor.surface_point_m(r.anchor), Vec3(0.01, 0.02, 0), 1e-15);
  EXPECT_THROW(at(x, law(-0.1, 1000)), std::invalid_argument);
  EXPECT_THROW(at(x, law(0.3, 0.0)), std::invalid_argument);
}

// The friction force at x with N = lambda(x) = max(0, lambda_bar - kA g(x)) from the normal
// contact (nodal_contact.h), dN/dx = -kA dg/dx.
FrictionResponse friction_with_contact(const RigidBody& body, const Vec3& x,
                                       const SurfaceLocation& anchor, const CoulombFrictionLaw& l) {
  const double lambda_bar = 0.2, kA = 500.0;
  const SurfacePoint s = body.query(x);
  const double N = std::max(0.0, lambda_bar - kA * s.signed_distance_m);
  return coulomb_friction(body, x, s, N, N > 0 ? Vec3(-kA * s.gap_gradient) : Vec3::Zero(), anchor,
                          l);
}

// -dF/dx by central differences with the anchor held (one Newton iterate's view). Step 1e-7 m
// on curvature radii of 5 cm and forces of 0.1-1 N: truncation (h/R)^2 ~ 1e-11 and round-off
// 1e-16 / 1e-7 ~ 1e-9 of a K of 1e2-1e3 N/m; 1e-6 relative covers both.
void expect_tangent_matches(const RigidBody& body, const Vec3& x, const SurfaceLocation& anchor,
                            const CoulombFrictionLaw& l, bool slipping) {
  const FrictionResponse r = friction_with_contact(body, x, anchor, l);
  ASSERT_EQ(r.slipping, slipping);
  const Mat3 fd = testing::minus_force_jacobian(
      [&](const Vec3& y) { return friction_with_contact(body, y, anchor, l).force_N; }, x);
  EXPECT_LT((r.stiffness_N_per_m - fd).norm(), 1e-6 * r.stiffness_N_per_m.norm())
      << "exact\n"
      << r.stiffness_N_per_m << "\nfd\n"
      << fd;
  if (slipping) {  // mu s (dN/dx)^T makes it unsymmetric
    EXPECT_GT((r.stiffness_N_per_m - r.stiffness_N_per_m.transpose()).norm(),
              0.01 * r.stiffness_N_per_m.norm());
  }
}

TEST(CoulombFrictionTangent, OnACylinderStickingAndSlipping) {
  const Cylinder cylinder(Vec3(0.01, 0, 0), Vec3(1, 1, 3), 0.05);
  const Vec3 x0 = cylinder.surface_point_m(SurfaceLocation{-1, Vec3(0.02, 0.7, 0)});
  const SurfaceLocation anchor = cylinder.query(x0).location;
  // 2 mm round and along, 0.1 mm in: N = 0.2 + 500 1e-4 = 0.25 N.
  const Vec3 n = cylinder.query(x0).outward_normal, along = cylinder.axis();
  const Vec3 x = x0 + 0.002 * n.cross(along) + 0.001 * along - 1e-4 * n;
  expect_tangent_matches(cylinder, x, anchor, law(0.5, 50), false);   // 0.11 N < 0.125 N
  expect_tangent_matches(cylinder, x, anchor, law(0.3, 1000), true);  // 2.2 N > 0.075 N
}

TEST(CoulombFrictionTangent, OnAMeshBodyStickingAndSlipping) {
  testing::write_obj(testing::temporary_path("friction.obj"),
                     testing::revolution_surface({-0.1, 0.0, 0.1}, {0.05, 0.055, 0.045}, 16));
  MeshBodyOptions o;
  o.import.up_axis = "+z";
  const auto body = load_mesh_body(testing::temporary_path("friction.obj"), o);
  const Vec3 x0(0.0515 * std::cos(0.2), 0.0515 * std::sin(0.2), 0.03);
  const SurfaceLocation anchor = body->query(x0).location;
  const Vec3 x = x0 + Vec3(-0.0004, 0.0015, 0.001) - 0.002 * body->query(x0).outward_normal;
  expect_tangent_matches(*body, x, anchor, law(1.0, 50), false);
  expect_tangent_matches(*body, x, anchor, law(0.3, 1000), true);
}

// A frame's trial force (place_anchor false, the vertex's answer without its closest point and
// location, the anchor's point kept in its NearFaces) against the whole return mapping from the
// tree's answers, on a smooth mesh body, sticking and slipping: the same force and tangent (the
// gap, normal and dn/dx from the kept faces are the tree's to round-off: docs/bodies.md; 1e-12
// relative allowed), the old anchor kept, and a slipping anchor placed only when asked.
TEST(CoulombFrictionAnchor, TrialForceWithoutPlacingTheAnchorIsTheWholeResponses) {
  testing::write_obj(testing::temporary_path("friction_trial.obj"),
                     testing::revolution_surface({-0.1, 0.0, 0.1}, {0.05, 0.055, 0.045}, 16));
  MeshBodyOptions o;
  o.import.up_axis = "+z";
  o.contact_surface = MeshBodyOptions::ContactSurface::smooth;
  const auto body = load_mesh_body(testing::temporary_path("friction_trial.obj"), o);
  const Vec3 x0(0.0515 * std::cos(0.2), 0.0515 * std::sin(0.2), 0.03);
  const SurfaceLocation anchor = body->query(x0).location;
  const Vec3 x = x0 + Vec3(-0.0004, 0.0015, 0.001) - 0.002 * body->query(x0).outward_normal;
  QueryParts force_only;
  force_only.closest_point = force_only.location = false;
  for (const bool slipping : {false, true}) {
    const CoulombFrictionLaw l = slipping ? law(0.3, 1000) : law(1.0, 50);
    const FrictionResponse whole =
        coulomb_friction(*body, x, body->query(x), 1.0, Vec3::Zero(), anchor, l);
    ASSERT_EQ(whole.slipping, slipping);
    NearFaces near;
    for (int frame = 0; frame < 2; ++frame) {  // the anchor's point found, then kept
      const SurfacePoint at_x = body->query_parts(x, near, force_only);
      const FrictionResponse trial =
          coulomb_friction(*body, x, at_x, 1.0, Vec3::Zero(), anchor, l, &near, false);
      EXPECT_EQ(trial.slipping, slipping);
      EXPECT_LT((trial.force_N - whole.force_N).norm(), 1e-12 * whole.force_N.norm());
      EXPECT_LT((trial.stiffness_N_per_m - whole.stiffness_N_per_m).norm(),
                1e-12 * whole.stiffness_N_per_m.norm());
      EXPECT_EQ(trial.anchor.face, anchor.face);
      EXPECT_EQ(trial.anchor.coordinates, anchor.coordinates);
    }
    if (slipping) {
      // The whole response placed the slid anchor mu N / k_t = 0.3 mm behind x's closest point
      // (the tangent plane's point put back on the surface: (0.3 mm)^2 / 2R = 1e-6 m on the 5 cm
      // radius; 1e-5 m allowed).
      EXPECT_NEAR((body->surface_point_m(whole.anchor) - body->query(x).closest_point_m).norm(),
                  3e-4, 1e-5);
    }
  }
}

TEST(CoulombFrictionAnchor, GrowingCylinderCarriesTheAnchor) {
  // Anchored at angle 30 degrees on a 5 cm cylinder, which then grows to 6 cm. A vertex on the
  // grown surface at angle 30 + 2 degrees is offset from the carried anchor by
  // R sin(2 degrees) round the surface (R = 6 cm: 2.094 mm), not by the 5 cm radius's 1.745 mm.
  Cylinder cylinder(Vec3::Zero(), Vec3::UnitZ(), 0.05);
  const double phi = M_PI / 6, dphi = M_PI / 90;
  const SurfaceLocation anchor =
      cylinder.query(Vec3(0.05 * std::cos(phi), 0.05 * std::sin(phi), 0.01)).location;
  cylinder.set_radius(0.06);
  expect_near(cylinder.surface_point_m(anchor),
              Vec3(0.06 * std::cos(phi), 0.06 * std::sin(phi), 0.01), 1e-15);
  const Vec3 e_r(std::cos(phi + dphi), std::sin(phi + dphi), 0), e_phi(-e_r.y(), e_r.x(), 0);
  const Vec3 x = (0.06 - 1e-4) * e_r + Vec3(0, 0, 0.01);
  const FrictionResponse r =
      coulomb_friction(cylinder, x, cylinder.query(x), 1.0, Vec3::Zero(), anchor, law(0.5, 100));
  EXPECT_FALSE(r.slipping);
  expect_near(r.force_N, -100 * 0.06 * std::sin(dphi) * e_phi, 1e-15);
}

TEST(CoulombFrictionAnchor, LongSlipOnACurvedBodyCommitsTheForceItGave) {
  // A vertex 60 degrees round a 5 cm cylinder from its anchor (a slip of 5.2 cm, as a morphing
  // body can make between two load steps) slips; from the anchor it commits, the same position
  // must give the same force, -mu N along the slip: the anchor sits mu N / k_t = 0.3 mm behind
  // the vertex's own foot, whatever the curvature between the old anchor and the vertex. What
  // is left is the projection of that 0.3 mm onto the curved surface, relative
  // (0.3 mm / R)^2 / 2 = 1.8e-5 of the force (measured 1.8e-5); an anchor measured from the old
  // one, 5 cm round, was centimetres off and turned the force.
  const Cylinder cylinder(Vec3::Zero(), Vec3::UnitZ(), 0.05);
  const SurfaceLocation start = cylinder.query(Vec3(0.06, 0, 0)).location;
  const double phi = M_PI / 3;
  const Vec3 x = (0.05 - 1e-5) * Vec3(std::cos(phi), std::sin(phi), 0) + Vec3(0, 0, 0.001);
  const FrictionResponse slip =
      coulomb_friction(cylinder, x, cylinder.query(x), 1.0, Vec3::Zero(), start, law(0.3, 1000));
  ASSERT_TRUE(slip.slipping);
  EXPECT_NEAR(slip.force_N.norm(), 0.3, 1e-12);
  const FrictionResponse again = coulomb_friction(cylinder, x, cylinder.query(x), 1.0, Vec3::Zero(),
                                                  slip.anchor, law(0.3, 1000));
  expect_near(again.force_N, slip.force_N, 1e-4 * 0.3);
}

TEST(CoulombFrictionAnchor, MorphingBodyDragsTheFabric) {
  // A faceted cylinder scaled by 1.2 about the point (0, 0, -0.1): the anchor at z = 0.05 rises
  // to -0.1 + 1.2 (0.15) = 0.08. A vertex left at z = 0.05 (now inside the grown body) is
  // pulled up towards it: 30 mm at k_t = 10 N/m, 0.3 N < mu N = 0.5 N, sticking. Its rings sit
  // between rings whose vertex normals are horizontal, so the pull along z is all tangential.
  BodyScaling about;
  about.about = BodyScaling::About::point;
  about.centre_m = Vec3(0, 0, -0.1);
  MeshBodyOptions o;
  o.import.up_axis = "+z";
  const std::vector<double> z = {-0.1, 0.0, 0.1, 0.2, 0.3};
  MorphingMeshBody body(
      import_surface(testing::revolution_surface(z, std::vector<double>(z.size(), 0.05), 24),
                     o.import),
      {}, o, about);
  const Vec3 x(0.049 * std::cos(0.1), 0.049 * std::sin(0.1), 0.05);
  const SurfaceLocation anchor = body.query(x).location;
  const Vec3 old_anchor = body.surface_point_m(anchor);
  body.set_morph(0.0, 1.2);
  const Vec3 carried = body.surface_point_m(anchor);
  expect_near(carried, about.centre_m + 1.2 * (old_anchor - about.centre_m), 1e-9);
  const FrictionResponse r =
      coulomb_friction(body, x, body.query(x), 1.0, Vec3::Zero(), anchor, law(0.5, 10));
  EXPECT_FALSE(r.slipping);
  EXPECT_NEAR(r.force_N.z(), 0.3, 1e-7);  // the anchor's z from float coordinates: 1e-8 m
}

}  // namespace
}  // namespace tightfit
