#include "fem/contact_set_prediction.h"

#include "contact/penalty_contact.h"

#include <deal.II/base/mpi.h>

namespace tightfit {

NodalContact unclipped_contact(const RigidBody& body, const Vec3& x_m, double multiplier_estimate_N,
                               double penalty_N_per_m) {
  const SurfacePoint s = body.query(x_m);
  return contact_with_multiplier(s, multiplier_estimate_N - penalty_N_per_m * s.signed_distance_m,
                                 penalty_N_per_m, true);
}

int predict_contact_set(const PatternMesh& pattern, const RigidBody& body, const DofVector& x,
                        const DofVector& increment, ContactNodes& nodes) {
  std::vector<signed char>& state = nodes.predicted_state;
  state.resize(pattern.n_owned_nodes(), 0);
  int n_changed = 0;
  for (int k = 0; k < pattern.n_owned_nodes(); ++k) {
    const int node = pattern.owned_nodes[k];
    const SurfacePoint s = body.query(pattern.node_position(x, node));
    const double lambda_bar = nodes.multiplier_N[k], kA = nodes.penalty_N_per_m[k];
    // The node's displacement: node_position reads its DoF values, here the increment's.
    const double gap_after =
        s.signed_distance_m + s.gap_gradient.dot(pattern.node_position(increment, node));
    const bool in_contact = contact_multiplier_N(lambda_bar, kA, s.signed_distance_m) > 0.0;
    const bool predicted = lambda_bar - kA * gap_after > 0.0;
    const signed char value = predicted == in_contact ? 0 : (predicted ? 1 : -1);
    n_changed += value != state[k];
    state[k] = value;
  }
  // Every rank goes on to solve again, or stops, alike.
  return dealii::Utilities::MPI::sum(n_changed, pattern.comm);
}

}  // namespace tightfit
