// Newton's model of the contact set: the nodal penalty force lambda n, lambda = max(0, lambda_bar
// - kA g) (contact/nodal_contact.h), is piecewise smooth, and a Newton step linearised on the
// nodes in contact at x drives nodes that are out of contact there into the body (or pulls nodes
// in contact off it) with no force against them: at the trial point the penalty kA (about 5e3
// N/m on the tops) answers a millimetre's step with newtons of residual, and the line search
// halves the step until only a few nodes cross. On the tops that was the whole of the linear
// convergence (docs/performance-bodies.md, "Newton on the tops").
//
// The remedy is the primal-dual active-set view of the semismooth Newton step (Hintermueller,
// Ito and Kunisch 2002): solve the step with each node's contact taken on the side of the kink
// that the step itself reaches, the linearised gap g + dg/dx . dx deciding, and repeat until the
// set the step predicts is the set it was solved with. A node predicted in contact that is out
// of contact at x takes the unclipped penalty force (lambda_bar - kA g) n (a pull, lambda < 0)
// with its tangent kA n (dg/dx)^T - lambda dn/dx; a node predicted out of contact that is in
// contact at x drops its contact and friction force and stiffness.
//
// Coulomb friction has a kink of its own, the cone's edge k_t |u| = mu lambda (u the offset from
// the anchor, contact/coulomb_friction.h), and the same treatment (the semismooth Newton step of
// Alart and Curnier's friction, as in Hueber, Stadler and Wohlmuth 2008): at each node the step
// predicts in contact, the linearised offset u + du/dx . dx and normal force lambda_bar - kA (g +
// dg/dx . dx) decide the branch. Where it differs from the node's own at x (or the node is out of
// contact at x), the step is solved on it: sticking, -k_t u with tangent k_t du/dx; slipping,
// -mu lambda t with tangent mu t (dlambda/dx)^T, t the predicted slip's direction held fixed and
// lambda unclipped. Without this a node the step brought into contact met the step's end with no
// friction in the model and slid: on a tube held by friction on a cone the nodes slid past their
// anchors, to where friction at its limit pulls back with no stiffness along the slip, and
// Newton stalled. Only the step changes: the line search and the stop rule read the true
// residual.
#pragma once

#include "bodies/rigid_body.h"
#include "fem/contact_nodes.h"
#include "fem/reference_mesh.h"

namespace tightfit {

// The contact and friction force on owned node k (pattern.owned_nodes()[k]) at p on the sides
// nodes.predicted holds for it (its own at p where that is empty or 0), and -d(force)/dx when
// `with_tangent`: exact, or with the contact's part symmetrised when `symmetric_contact`
// (contact/nodal_contact.h). Returns false where the node feels neither.
bool model_node_contact(const RigidBody& body, const ContactNodes& nodes, int k, const Vec3& p,
                        bool with_tangent, bool symmetric_contact, Vec3& force_N,
                        Mat3& stiffness_N_per_m);

// Sets nodes.predicted of this rank's nodes for the Newton step `increment` from x (above).
// Returns how many nodes' contact side or friction branch, on every rank, differ from those
// nodes.predicted held before (0: the step was solved on the sides it predicts); collective.
int predict_contact_set(const ReferenceMesh& pattern, const RigidBody& body, const DofVector& x,
                        const DofVector& increment, ContactNodes& nodes);

}  // namespace tightfit
