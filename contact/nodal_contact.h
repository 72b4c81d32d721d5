// Frictionless augmented-Lagrangian contact of one vertex with a rigid body, with the
// stiffness an implicit solver needs.
//
// With the penalty stiffness kA = k A0 (k in Pa/m, A0 the vertex's rest area) and the
// multiplier estimate lambda_bar (N), the contact force on the vertex is penalty_contact.h's
//   lambda n,  lambda = max(0, lambda_bar - kA g)  (g the signed distance, n the body normal),
// the derivative of the potential max(0, lambda_bar - kA g)^2 / (2 kA). Updating lambda_bar to
// lambda after each converged solve drives g to zero for any kA (Uzawa's iteration), so the
// pressure does not depend on the penalty.
#pragma once

#include "bodies/rigid_body.h"
#include "core/types.h"

namespace tightfit {

struct NodalContact {
  double gap_m = 0.0;
  double multiplier_N = 0.0;  // lambda >= 0
  Vec3 normal = Vec3::UnitZ();
  Vec3 force_N = Vec3::Zero();  // lambda n, on the garment
  // -d(force)/dx = kA n (dg/dx)^T - lambda dn/dx when active, N/m, symmetrised (the linear
  // solvers may be symmetric ones). dg/dx and dn/dx are the body's own (SurfacePoint): exact
  // for the analytic bodies, where dg/dx = n and dn/dx is symmetric so nothing is lost; a mesh
  // body's smooth normal makes the exact derivative slightly unsymmetric.
  Mat3 stiffness_N_per_m = Mat3::Zero();
  // The same unsymmetrised, kA n (dg/dx)^T - lambda dn/dx: the exact derivative, for solvers
  // that take an unsymmetric matrix (it equals the symmetrised one on the analytic bodies).
  Mat3 exact_stiffness_N_per_m = Mat3::Zero();
  // d(lambda)/dx = -kA dg/dx while in contact, N/m (friction's cone scales with it).
  Vec3 multiplier_gradient_N_per_m = Vec3::Zero();
};

// `with_stiffness` false skips the stiffness (the force alone).
NodalContact nodal_contact(const RigidBody& body, const Vec3& x_m, double multiplier_estimate_N,
                           double penalty_N_per_m, bool with_stiffness);

// The contact at a surface point with a given multiplier lambda (N), not clipped at zero: the
// force lambda n and its derivatives as above. nodal_contact() uses it once lambda > 0; the FE
// backend's contact set prediction uses it for a node the step brings into contact.
NodalContact contact_with_multiplier(const SurfacePoint& s, double multiplier_N,
                                     double penalty_N_per_m, bool with_stiffness);

}  // namespace tightfit
