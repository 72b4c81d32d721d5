// Quasi-static Coulomb friction between a garment vertex and a rigid body, by a return mapping
// onto the Coulomb cone from a tangential penalty trial force (docs/model.md, "Friction").
//
// Each vertex in contact keeps an anchor: the point of the body's own surface where it sticks
// (a SurfaceLocation: face and barycentric coordinates, or an analytic body's parameters), so
// that a body that grows or morphs carries the anchor with it and drags the fabric where it
// sticks. With a = body.surface_point_m(anchor), the normal n at x and P = I - n n^T,
//   u = P (x - a),  f_trial = -k_t u                        (k_t the tangential penalty, N/m)
//   stick, |f_trial| <= mu N:  f = f_trial
//   slip:                      f = -mu N u / |u|, and the anchor slides along u to where
//                              |f_trial| = mu N (the return mapping)
// N the normal contact force (the multiplier lambda of nodal_contact.h). The law is path
// dependent: the anchor is history, updated only once a state is accepted (commit it after
// the solve converged).
#pragma once

#include "bodies/rigid_body.h"
#include "core/types.h"

namespace tightfit {

struct CoulombFrictionLaw {
  double friction_coefficient = 0.3;        // mu, >= 0
  double tangential_penalty_N_per_m = 1e3;  // k_t > 0: the stiffness of sticking
};

struct FrictionResponse {
  Vec3 force_N = Vec3::Zero();  // tangential, on the garment vertex
  // -d(force)/dx, N/m: the consistent tangent of the return mapping, with the turning of the
  // normal (dn/dx) and, while slipping, the change of mu N with x. Not symmetric when slipping.
  Mat3 stiffness_N_per_m = Mat3::Zero();
  bool slipping = false;
  // The anchor after the return mapping: unchanged while sticking; the point the spring pulls
  // from at the cone's edge while slipping. Keep it once the state is accepted.
  SurfaceLocation anchor;
};

// The anchor's offset in the tangent plane at x, u = P (x - a), and du/dx.
struct TangentialOffset {
  Vec3 u = Vec3::Zero();
  Mat3 du_dx = Mat3::Zero();
};
// `near` (when given) is x's kept faces, from which a mesh body finds the anchor's point.
TangentialOffset tangential_offset(const RigidBody& body, const Vec3& x_m, const SurfacePoint& at_x,
                                   const SurfaceLocation& anchor, const NearFaces* near = nullptr);

// The sticking branch of the return mapping on its own: f = -k_t u, -df/dx = k_t du/dx.
FrictionResponse sticking_friction(const TangentialOffset& offset,
                                   double tangential_penalty_N_per_m);

// The slipping branch with its direction t held fixed: f = -mu N t, -df/dx = mu t (dN/dx)^T.
// N is not clipped at zero (the FE contact set prediction continues the law to a node the Newton
// step carries into contact, whose N at x is still a pull).
FrictionResponse slipping_friction_along(const Vec3& direction, double friction_coefficient,
                                         double normal_force_N,
                                         const Vec3& normal_force_gradient_N_per_m);

// `at_x` is body.query(x_m) (its normal, dn/dx and location); `normal_force_N` is N >= 0 and
// `normal_force_gradient_N_per_m` dN/dx (nodal_contact.h: -kA dg/dx while in contact). A vertex
// out of contact (N = 0) feels no friction and its anchor resets to its closest point.
// Throws std::invalid_argument for mu < 0 or k_t <= 0. `near` (if given) is x's own
// RigidBody::query_near memory, for the query that places a slipping anchor near x.
// `place_anchor` false: a caller that keeps only the force and its tangent (a trial state of an
// explicit frame) skips the query that places a slipping anchor (the response's anchor is then
// the old one) and may pass an `at_x` without its closest point and location.
FrictionResponse coulomb_friction(const RigidBody& body, const Vec3& x_m, const SurfacePoint& at_x,
                                  double normal_force_N, const Vec3& normal_force_gradient_N_per_m,
                                  const SurfaceLocation& anchor, const CoulombFrictionLaw& law,
                                  NearFaces* near = nullptr, bool place_anchor = true);

}  // namespace tightfit
