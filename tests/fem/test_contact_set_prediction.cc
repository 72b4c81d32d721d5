// The step's model of a node whose contact or friction the Newton step carries across a kink
// (fem/contact_set_prediction.h): the unclipped penalty force, and friction on the branch the
// step predicts, against their closed forms, with their tangents against central finite
// differences.
#include "bodies/cylinder.h"
#include "central_difference.h"
#include "contact/nodal_contact.h"
#include "fem/contact_set_prediction.h"

#include <gtest/gtest.h>

namespace tightfit {
namespace {

const double penalty = 2e4, multiplier = 0.3;
const double mu = 0.4, tangential_N_per_m = 5e3;  // k_t = 5e3 N/m on a node of 1 cm^2

const Cylinder& cylinder() {
  static const Cylinder body(Vec3(0.01, 0, 0), Vec3(1, 1, 3).normalized(), 0.05);
  return body;
}

// One node with the multiplier and penalty above, on `side`; with friction (mu > 0) its anchor
// at the closest point of `anchor_near`.
ContactNodes one_node(const PredictedSide& side, double friction_coefficient,
                      const Vec3& anchor_near = Vec3::Zero()) {
  ContactNodes nodes;
  nodes.penalty_N_per_m = {penalty};
  nodes.multiplier_N = {multiplier};
  nodes.friction = FrictionAnchors(friction_coefficient, tangential_N_per_m / 1e-4, {1e-4});
  nodes.friction.place(cylinder(), {anchor_near});
  nodes.predicted = {side};
  return nodes;
}

struct Model {
  Vec3 force_N;
  Mat3 stiffness_N_per_m;  // exact (unsymmetrised contact)
  bool touching;
};

Model model(const ContactNodes& nodes, const Vec3& x) {
  Model m;
  m.touching =
      model_node_contact(cylinder(), nodes, 0, x, true, false, m.force_N, m.stiffness_N_per_m);
  return m;
}

// -d(force)/dx of the model at x by central differences (step 1e-7 m; as in
// tests/contact/test_nodal_contact.cc, round-off stays near 1e-9 N/m against |K| ~ 2e4 N/m).
Mat3 minus_force_derivative(const ContactNodes& nodes, const Vec3& x) {
  return testing::minus_force_jacobian([&](const Vec3& y) { return model(nodes, y).force_N; }, x);
}

PredictedSide side(signed char contact, FrictionBranch friction = FrictionBranch::own,
                   const Vec3& slip_direction = Vec3::Zero()) {
  PredictedSide s;
  s.contact = contact;
  s.friction = friction;
  s.slip_direction = slip_direction;
  return s;
}

// A point 2 mm outside the cylinder: lambda = 0.3 - 2e4 * 0.002 = -39.7 N, a pull.
SurfacePoint on_surface() {
  return cylinder().query(Vec3(0.04, 0.031, 0.02));
}
Vec3 outside() {
  return on_surface().closest_point_m + 2e-3 * on_surface().outward_normal;
}
// A unit tangent of the surface at on_surface().
Vec3 tangent() {
  const Vec3 n = on_surface().outward_normal;
  return n.cross(Vec3::UnitZ()).normalized();
}

TEST(ContactSetPrediction, UnclippedForceOutsideTheBodyPullsAndItsTangentIsExact) {
  const ContactNodes nodes = one_node(side(1), 0.0);
  const Model m = model(nodes, outside());
  ASSERT_TRUE(m.touching);
  const Vec3 n = on_surface().outward_normal;
  EXPECT_LT((m.force_N - (multiplier - penalty * 2e-3) * n).norm(), 1e-9);
  const Mat3 K_fd = minus_force_derivative(nodes, outside());
  EXPECT_LT((m.stiffness_N_per_m - K_fd).norm(), 1e-5 * penalty);
  // The symmetrised contact tangent is the symmetric part of the exact one.
  Vec3 f;
  Mat3 K_symmetric;
  model_node_contact(cylinder(), nodes, 0, outside(), true, true, f, K_symmetric);
  EXPECT_LT((K_symmetric - 0.5 * (K_fd + K_fd.transpose())).norm(), 1e-5 * penalty);
}

TEST(ContactSetPrediction, UnclippedForceInContactIsTheNodalContact) {
  const Vec3 inside(0.04, 0.031, 0.02);
  const Model u = model(one_node(side(1), 0.0), inside);
  const NodalContact c = nodal_contact(cylinder(), inside, multiplier, penalty, true);
  ASSERT_GT(c.multiplier_N, 0.0);
  EXPECT_LT((u.force_N - c.force_N).norm(), 1e-12);
  EXPECT_LT((u.stiffness_N_per_m - c.exact_stiffness_N_per_m).norm(), 1e-9);
  EXPECT_LT((u.stiffness_N_per_m - minus_force_derivative(one_node(side(1), 0.0), inside)).norm(),
            1e-5 * penalty);
}

TEST(ContactSetPrediction, NodeOutOfContactPredictedToStickTakesTheTangentialSpring) {
  // The anchor 3 mm along the surface from the node's closest point.
  const Vec3 anchor_near = on_surface().closest_point_m + 3e-3 * tangent();
  const ContactNodes nodes = one_node(side(1, FrictionBranch::stick), mu, anchor_near);
  const Model m = model(nodes, outside());
  // -k_t u with u = P (x - a), a the anchor's point and P the tangent plane at x: whatever
  // lambda (a pull here), the spring, not the cone, in the step's model.
  const Vec3 n = on_surface().outward_normal;
  const Vec3 d = outside() - cylinder().query(anchor_near).closest_point_m;
  const Vec3 u = d - n.dot(d) * n;
  EXPECT_LT((m.force_N - (multiplier - penalty * 2e-3) * n + tangential_N_per_m * u).norm(), 1e-9);
  EXPECT_LT((m.stiffness_N_per_m - minus_force_derivative(nodes, outside())).norm(),
            1e-5 * penalty);
}

TEST(ContactSetPrediction, NodePredictedToSlipTakesTheConeAlongTheFixedDirection) {
  const Vec3 t = tangent();
  const ContactNodes nodes = one_node(side(1, FrictionBranch::slip, t), mu, outside());
  const Model m = model(nodes, outside());
  const double lambda = multiplier - penalty * 2e-3;
  EXPECT_LT((m.force_N - lambda * on_surface().outward_normal + mu * lambda * t).norm(), 1e-9);
  EXPECT_LT((m.stiffness_N_per_m - minus_force_derivative(nodes, outside())).norm(),
            1e-5 * penalty);
  // In contact (lambda > 0) the same model, the cone's force against the slip.
  const Vec3 inside = on_surface().closest_point_m - 1e-4 * on_surface().outward_normal;
  const ContactNodes held = one_node(side(0, FrictionBranch::slip, t), mu, inside);
  const Model in = model(held, inside);
  const double lambda_in = multiplier + penalty * 1e-4;
  EXPECT_LT((in.force_N - lambda_in * on_surface().outward_normal + mu * lambda_in * t).norm(),
            1e-9);
  EXPECT_LT((in.stiffness_N_per_m - minus_force_derivative(held, inside)).norm(), 1e-5 * penalty);
}

TEST(ContactSetPrediction, NodeInContactPredictedToStickIsNotClippedToTheCone) {
  // In contact with lambda = 2.3 N; the anchor 1 mm away: the trial force k_t |u| = 5 N exceeds
  // mu lambda = 0.92 N, so the node slips on its own branch but sticks on the predicted one.
  const Vec3 inside = on_surface().closest_point_m - 1e-4 * on_surface().outward_normal;
  const Vec3 anchor_near = on_surface().closest_point_m + 1e-3 * tangent();
  const ContactNodes own = one_node(side(0), mu, anchor_near);
  const ContactNodes stick = one_node(side(0, FrictionBranch::stick), mu, anchor_near);
  const double lambda = multiplier + penalty * 1e-4;
  const Vec3 n = on_surface().outward_normal;
  const double own_friction_N = (model(own, inside).force_N - lambda * n).norm();
  const double stick_friction_N = (model(stick, inside).force_N - lambda * n).norm();
  EXPECT_NEAR(own_friction_N, mu * lambda, 1e-9);
  EXPECT_NEAR(stick_friction_N, tangential_N_per_m * 1e-3, 0.02 * tangential_N_per_m * 1e-3);
  EXPECT_LT((model(stick, inside).stiffness_N_per_m - minus_force_derivative(stick, inside)).norm(),
            1e-5 * penalty);
}

TEST(ContactSetPrediction, NodePredictedOffFeelsNothing) {
  const Vec3 inside = on_surface().closest_point_m - 1e-4 * on_surface().outward_normal;
  const Model m = model(one_node(side(-1), mu, inside), inside);
  EXPECT_FALSE(m.touching);
  EXPECT_EQ(m.force_N, Vec3::Zero());
  EXPECT_EQ(m.stiffness_N_per_m, Mat3::Zero());
}

}  // namespace
}  // namespace tightfit
