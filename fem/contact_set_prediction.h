// Newton's model of the contact set: the nodal penalty force lambda n, lambda = max(0, lambda_bar
// - kA g) (contact/nodal_contact.h), is piecewise smooth, and a Newton step linearised on the
// nodes in contact at x drives nodes that are out of contact there into the body (or pulls nodes
// in contact off it) with no force against them: at the trial point the penalty kA (about 5e3
// N/m on the tops) answers a millimetre's step with newtons of residual, and the line search
// halves the step until only a few nodes cross. On the tops that was the whole of the linear
// convergence (docs/performance.md, "Newton on the tops").
//
// The remedy is the primal-dual active-set view of the semismooth Newton step (Hintermueller,
// Ito and Kunisch 2002): solve the step with each node's contact taken on the side of the kink
// that the step itself reaches, the linearised gap g + dg/dx . dx deciding, and repeat until the
// set the step predicts is the set it was solved with. A node predicted in contact that is out
// of contact at x takes the unclipped penalty force (lambda_bar - kA g) n (a pull, lambda < 0)
// with its tangent kA n (dg/dx)^T - lambda dn/dx; a node predicted out of contact that is in
// contact at x drops its contact and friction force and stiffness. Only the step changes: the
// line search and the stop rule read the true residual.
#pragma once

#include "contact/nodal_contact.h"
#include "contact/rigid_body.h"
#include "fem/contact_nodes.h"
#include "fem/pattern_mesh.h"

namespace tightfit {

// lambda n with lambda = lambda_bar - kA g not clipped at zero, and its exact tangent
// -d(force)/dx = kA n (dg/dx)^T - lambda dn/dx, N/m (the symmetrised one in stiffness_N_per_m).
NodalContact unclipped_contact(const RigidBody& body, const Vec3& x_m, double multiplier_estimate_N,
                               double penalty_N_per_m);

// Sets nodes.predicted_state of this rank's nodes for the Newton step `increment` from x: +1
// where the linearised gap puts a node out of contact at x in contact after the step, -1 where
// it puts a node in contact at x out of it, 0 elsewhere. Returns how many nodes' predictions, on
// every rank, differ from those nodes.predicted_state held before (0: the step was solved with
// the set it predicts); collective.
int predict_contact_set(const PatternMesh& pattern, const RigidBody& body, const DofVector& x,
                        const DofVector& increment, ContactNodes& nodes);

}  // namespace tightfit
