#include "fem/contact_set_prediction.h"

#include "contact/penalty_contact.h"

namespace tightfit {

NodalContact unclipped_contact(const RigidBody& body, const Vec3& x_m, double multiplier_estimate_N,
                               double penalty_N_per_m) {
  const SurfacePoint s = body.query(x_m);
  return contact_with_multiplier(s, multiplier_estimate_N - penalty_N_per_m * s.signed_distance_m,
                                 penalty_N_per_m, true);
}

int predict_contact_set(const PatternMesh& pattern, const RigidBody& body,
                        const dealii::Vector<double>& x, const dealii::Vector<double>& increment,
                        ContactNodes& nodes) {
  std::vector<signed char>& state = nodes.predicted_state;
  state.resize(pattern.n_nodes(), 0);
  int n_changed = 0;
  for (int node = 0; node < pattern.n_nodes(); ++node) {
    const SurfacePoint s = body.query(pattern.node_position(x, node));
    const double lambda_bar = nodes.multiplier_N[node], kA = nodes.penalty_N_per_m[node];
    // The node's displacement: node_position reads its DoF values, here the increment's.
    const double gap_after =
        s.signed_distance_m + s.gap_gradient.dot(pattern.node_position(increment, node));
    const bool in_contact = contact_multiplier_N(lambda_bar, kA, s.signed_distance_m) > 0.0;
    const bool predicted = lambda_bar - kA * gap_after > 0.0;
    const signed char value = predicted == in_contact ? 0 : (predicted ? 1 : -1);
    n_changed += value != state[node];
    state[node] = value;
  }
  return n_changed;
}

}  // namespace tightfit
