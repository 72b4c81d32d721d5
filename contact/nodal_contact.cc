#include "contact/nodal_contact.h"

#include "contact/penalty_contact.h"

namespace tightfit {

NodalContact contact_with_multiplier(const SurfacePoint& s, double multiplier_N,
                                     double penalty_N_per_m, bool with_stiffness) {
  NodalContact c;
  c.gap_m = s.signed_distance_m;
  c.normal = s.outward_normal;
  c.multiplier_N = multiplier_N;
  c.force_N = c.multiplier_N * c.normal;
  if (!with_stiffness) return c;
  const Mat3 K = penalty_N_per_m * c.normal * s.gap_gradient.transpose() -
                 c.multiplier_N * s.normal_derivative_per_m;
  c.stiffness_N_per_m = 0.5 * (K + K.transpose());
  c.exact_stiffness_N_per_m = K;
  c.multiplier_gradient_N_per_m = -penalty_N_per_m * s.gap_gradient;
  return c;
}

NodalContact nodal_contact(const RigidBody& body, const Vec3& x_m, double multiplier_estimate_N,
                           double penalty_N_per_m, bool with_stiffness) {
  const SurfacePoint s = body.query(x_m);
  const double multiplier_N =
      contact_multiplier_N(multiplier_estimate_N, penalty_N_per_m, s.signed_distance_m);
  if (multiplier_N > 0.0)
    return contact_with_multiplier(s, multiplier_N, penalty_N_per_m, with_stiffness);
  NodalContact c;
  c.gap_m = s.signed_distance_m;
  c.normal = s.outward_normal;
  return c;
}

}  // namespace tightfit
