#include "fem/contact_set_prediction.h"

#include "contact/nodal_contact.h"
#include "contact/penalty_contact.h"

#include <deal.II/base/mpi.h>

namespace tightfit {

namespace {

// The friction branch the step reaches at a node it predicts in contact with normal force
// `lambda_after` > 0 (header): the node's own when it is in contact at x (lambda > 0) on the same
// branch there.
PredictedSide predicted_friction(const FrictionAnchors& friction, int k, const RigidBody& body,
                                 const Vec3& p, const SurfacePoint& s, const Vec3& dx,
                                 double lambda, double lambda_after) {
  PredictedSide side;
  const TangentialOffset offset = friction.offset(k, body, p, s);
  const Vec3 u_after = offset.u + offset.du_dx * dx;
  const double kt = friction.tangential_stiffness_N_per_m(k);
  const double mu = friction.friction_coefficient();
  const bool sticks_after = kt * u_after.norm() <= mu * lambda_after;
  if (lambda > 0.0 && (kt * offset.u.norm() <= mu * lambda) == sticks_after) return side;
  side.friction = sticks_after ? FrictionBranch::stick : FrictionBranch::slip;
  // Slipping: kt |u_after| > mu lambda_after > 0, so u_after has a direction.
  if (!sticks_after) side.slip_direction = u_after.normalized();
  return side;
}

}  // namespace

bool model_node_contact(const RigidBody& body, const ContactNodes& nodes, int k, const Vec3& p,
                        bool with_tangent, bool symmetric_contact, Vec3& force_N,
                        Mat3& stiffness_N_per_m) {
  force_N = Vec3::Zero();
  stiffness_N_per_m = Mat3::Zero();
  const PredictedSide side = nodes.predicted.empty() ? PredictedSide() : nodes.predicted[k];
  if (side.contact < 0) return false;  // the step leaves contact here: no contact, no friction
  const SurfacePoint s = nodes.query(body, k, p);
  const double lambda_bar = nodes.multiplier_N[k], kA = nodes.penalty_N_per_m[k];
  // Predicted in contact: the penalty force unclipped (a pull while p is outside the body).
  const double lambda = side.contact > 0
                            ? lambda_bar - kA * s.signed_distance_m
                            : contact_multiplier_N(lambda_bar, kA, s.signed_distance_m);
  if (side.contact == 0 && lambda <= 0.0) return false;
  const NodalContact c = contact_with_multiplier(s, lambda, kA, with_tangent);
  force_N = c.force_N;
  stiffness_N_per_m = symmetric_contact ? c.stiffness_N_per_m : c.exact_stiffness_N_per_m;
  const FrictionAnchors& friction = nodes.friction;
  if (!friction.active()) return true;
  // Friction's cone mu lambda moves with the node: its tangent has mu s (dlambda/dx)^T.
  const Vec3& dlambda_dx = c.multiplier_gradient_N_per_m;
  FrictionResponse r;
  switch (side.friction) {
    case FrictionBranch::own:
      r = friction.response(k, body, p, s, lambda, dlambda_dx, nodes.near(k));
      break;
    case FrictionBranch::stick:
      r = sticking_friction(friction.offset(k, body, p, s),
                            friction.tangential_stiffness_N_per_m(k));
      break;
    case FrictionBranch::slip:
      r = slipping_friction_along(side.slip_direction, friction.friction_coefficient(), lambda,
                                  dlambda_dx);
      break;
  }
  force_N += r.force_N;
  stiffness_N_per_m += r.stiffness_N_per_m;
  return true;
}

int predict_contact_set(const ReferenceMesh& pattern, const RigidBody& body, const DofVector& x,
                        const DofVector& increment, ContactNodes& nodes) {
  std::vector<PredictedSide>& predicted = nodes.predicted;
  predicted.resize(pattern.n_owned_nodes());
  int n_changed = 0;
  for (int k = 0; k < pattern.n_owned_nodes(); ++k) {
    const int node = pattern.owned_nodes()[k];
    const Vec3 p = pattern.node_position(x, node);
    // The node's displacement: node_position reads its DoF values, here the increment's.
    const Vec3 dx = pattern.node_position(increment, node);
    const SurfacePoint s = nodes.query(body, k, p);
    const double lambda_bar = nodes.multiplier_N[k], kA = nodes.penalty_N_per_m[k];
    const double lambda = contact_multiplier_N(lambda_bar, kA, s.signed_distance_m);
    const double lambda_after = lambda_bar - kA * (s.signed_distance_m + s.gap_gradient.dot(dx));
    const bool in_contact = lambda > 0.0, in_contact_after = lambda_after > 0.0;
    PredictedSide side;
    if (in_contact_after && nodes.friction.active())
      side = predicted_friction(nodes.friction, k, body, p, s, dx, lambda, lambda_after);
    side.contact = in_contact_after == in_contact ? 0 : (in_contact_after ? 1 : -1);
    n_changed += !side.same_branches(predicted[k]);
    predicted[k] = side;
  }
  // Every rank goes on to solve again, or stops, alike.
  return dealii::Utilities::MPI::sum(n_changed, pattern.comm());
}

}  // namespace tightfit
