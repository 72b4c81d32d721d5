// Penalty contact between garment vertices and a rigid body (frictionless), augmented by a
// multiplier estimate.
//
// A vertex of rest area A0 at signed distance g from the body (g < 0 inside) with multiplier
// estimate lambda_bar (N) is pushed out along the body's normal n by
//   f = lambda n,  lambda = max(0, lambda_bar - k A0 g)          (k in Pa/m)
// With lambda_bar = 0 this is the plain penalty k A0 d n (d = -g the depth), whose equilibrium
// leaves the vertex d = p / k inside the body. Setting lambda_bar to the lambda of a settled
// state and settling again (Uzawa's iteration) drives g to zero whatever k, so the pressure
// does not depend on the penalty. tightfit sets k = beta Y / h^2 (Y the law's stiffness scale,
// h the mean rest edge length, beta the "Penalty factor") so that d / h stays of order
// (strain / beta) whatever the fabric and mesh: see docs/model.md ("Contact").
#pragma once

#include "bodies/rigid_body.h"
#include "core/surface_state.h"

#include <vector>

namespace tightfit {

// k = beta * stiffness / edge^2, Pa/m.
double penalty_stiffness_Pa_per_m(double penalty_factor, double stiffness_scale_N_per_m,
                                  double mean_edge_length_m);

// lambda = max(0, lambda_bar - kA g), N: the contact force's magnitude, kA = k A0 in N/m.
inline double contact_multiplier_N(double multiplier_estimate_N, double penalty_N_per_m,
                                   double gap_m) {
  const double lambda = multiplier_estimate_N - penalty_N_per_m * gap_m;
  return lambda > 0.0 ? lambda : 0.0;
}

// Fills state.contact_force_N, state.in_contact and state.gap_m for state.positions_m.
// `rest_vertex_area_m2` is the barycentric rest area of each vertex; `multiplier_N` the
// multiplier estimate of each (empty: all zero, the plain penalty). A vertex is in contact
// where its force is not zero.
void apply_penalty_contact(const RigidBody& body, double stiffness_Pa_per_m,
                           const std::vector<double>& rest_vertex_area_m2, SurfaceState& state,
                           const std::vector<double>& multiplier_N = {});

// Contact force on one vertex (zero when outside the body and its multiplier is zero), N.
Vec3 penalty_force_N(const SurfacePoint& s, double stiffness_Pa_per_m, double rest_area_m2,
                     double multiplier_N = 0.0);

// The damper along the normal of a vertex's contact spring: the force -c (v . d) d with
// c = 2 zeta sqrt(kA m) (N s/m), d the gap's gradient, so that a vertex of mass m on its spring
// kA (N/m) moving along d obeys m g'' + c g' + kA g = 0: damping ratio zeta, 1 critical.
// Motion along the body (v . d = 0) is not damped.
double contact_damper_N_s_per_m(double damping_ratio, double penalty_N_per_m, double mass_kg);

}  // namespace tightfit
