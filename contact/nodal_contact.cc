#include "contact/nodal_contact.h"

#include "contact/penalty_contact.h"

namespace tightfit {

NodalContact nodal_contact(const RigidBody& body, const Vec3& x_m, double multiplier_estimate_N,
                           double penalty_N_per_m, double normal_step_m) {
  NodalContact c;
  const SurfacePoint s = body.query(x_m);
  c.gap_m = s.signed_distance_m;
  c.normal = s.outward_normal;
  c.multiplier_N = contact_multiplier_N(multiplier_estimate_N, penalty_N_per_m, c.gap_m);
  if (c.multiplier_N <= 0.0) return c;
  c.force_N = c.multiplier_N * c.normal;
  if (normal_step_m <= 0.0) return c;
  // dg/dx = n for a signed distance; dn/dx (the body's curvature) by central differences.
  Mat3 dn_dx;
  for (int j = 0; j < 3; ++j) {
    const Vec3 step = normal_step_m * Vec3::Unit(j);
    dn_dx.col(j) = (body.query(x_m + step).outward_normal - body.query(x_m - step).outward_normal) /
                   (2.0 * normal_step_m);
  }
  c.stiffness_N_per_m = penalty_N_per_m * c.normal * c.normal.transpose() -
                        c.multiplier_N * 0.5 * (dn_dx + dn_dx.transpose());
  return c;
}

}  // namespace tightfit
