#include "contact/penalty_contact.h"

#include <cmath>

namespace tightfit {

double penalty_stiffness_Pa_per_m(double penalty_factor, double stiffness_scale_N_per_m,
                                  double mean_edge_length_m) {
  return penalty_factor * stiffness_scale_N_per_m / (mean_edge_length_m * mean_edge_length_m);
}

Vec3 penalty_force_N(const SurfacePoint& s, double stiffness_Pa_per_m, double rest_area_m2,
                     double multiplier_N) {
  return contact_multiplier_N(multiplier_N, stiffness_Pa_per_m * rest_area_m2,
                              s.signed_distance_m) *
         s.outward_normal;
}

double contact_damper_N_s_per_m(double damping_ratio, double penalty_N_per_m, double mass_kg) {
  return 2.0 * damping_ratio * std::sqrt(penalty_N_per_m * mass_kg);
}

void apply_penalty_contact(const RigidBody& body, double stiffness_Pa_per_m,
                           const std::vector<double>& rest_vertex_area_m2, SurfaceState& state,
                           const std::vector<double>& multiplier_N) {
  const std::size_t n = state.positions_m.size();
  state.contact_force_N.assign(n, Vec3::Zero());
  state.in_contact.assign(n, 0);
  state.gap_m.assign(n, 0.0);
  for (std::size_t v = 0; v < n; ++v) {
    const SurfacePoint s = body.query(state.positions_m[v]);
    state.gap_m[v] = s.signed_distance_m;
    state.contact_force_N[v] = penalty_force_N(s, stiffness_Pa_per_m, rest_vertex_area_m2[v],
                                               multiplier_N.empty() ? 0.0 : multiplier_N[v]);
    state.in_contact[v] = state.contact_force_N[v] != Vec3::Zero();
  }
}

}  // namespace tightfit
