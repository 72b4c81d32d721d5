// Penalty contact between garment vertices and a rigid body (frictionless).
//
// A vertex of rest area A0 that is a depth d = max(0, -signed distance) inside the body is
// pushed out along the body's normal by f = k A0 d n (k in Pa/m: pressure per unit depth).
// At equilibrium the penetration is d = p / k; tightfit sets k = beta Y / h^2 (Y the law's
// stiffness scale, h the mean rest edge length, beta the "Penalty factor") so that d / h stays
// of order (strain / beta) whatever the fabric and mesh: see docs/model.md ("Contact").
#pragma once

#include "contact/rigid_body.h"
#include "core/surface_state.h"

#include <vector>

namespace tightfit {

// k = beta * stiffness / edge^2, Pa/m.
double penalty_stiffness_Pa_per_m(double penalty_factor, double stiffness_scale_N_per_m,
                                  double mean_edge_length_m);

// Fills state.contact_force_N, state.in_contact and state.gap_m for state.positions_m.
// `rest_vertex_area_m2` is the barycentric rest area of each vertex.
void apply_penalty_contact(const RigidBody& body, double stiffness_Pa_per_m,
                           const std::vector<double>& rest_vertex_area_m2, SurfaceState& state);

// Contact force on one vertex (zero when outside the body), N, and the force's derivative
// along the normal (d f / d x = -k A0 n n^T inside): for implicit solvers.
Vec3 penalty_force_N(const SurfacePoint& s, double stiffness_Pa_per_m, double rest_area_m2);

}  // namespace tightfit
