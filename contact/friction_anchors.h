// The friction state of a whole garment: one anchor per vertex (contact/coulomb_friction.h) and
// each vertex's share of the tangential penalty, so that both backends apply the same law in
// the same way (docs/model.md, "Friction").
//
// Quasi-static and path dependent: a load step is one increment. Its anchors are those of the
// last accepted state; every force evaluation inside the step (each RK4 stage, each Newton
// iterate) takes the return mapping from them, and only the converged state commits the
// returned anchors. A vertex out of contact keeps its closest point as its anchor, where it
// will stick when it touches.
#pragma once

#include "bodies/rigid_body.h"
#include "contact/coulomb_friction.h"

#include <vector>

namespace tightfit {

class FrictionAnchors {
 public:
  FrictionAnchors() = default;
  // mu >= 0 (0: no friction, every call below is a no-op); the tangential penalty of vertex i is
  // `tangential_stiffness_Pa_per_m` times its rest area (N/m), the same scaling as the normal
  // penalty's k A0. Throws std::invalid_argument for mu < 0 or a stiffness that is not positive
  // while mu > 0.
  FrictionAnchors(double friction_coefficient, double tangential_stiffness_Pa_per_m,
                  std::vector<double> rest_vertex_area_m2);

  bool active() const { return mu_ > 0.0; }
  bool placed() const { return !anchor_.empty(); }
  // Every anchor at its vertex's closest point on the body as it is now.
  void place(const RigidBody& body, const std::vector<Vec3>& positions_m);
  // The return mapping for vertex i at x (`at_x` = body.query(x)) under normal force N with
  // gradient dN/dx (Vec3::Zero() when only the force is wanted).
  // `near`: x's RigidBody::query_near memory, if kept; `place_anchor` false: the force and its
  // tangent only (coulomb_friction).
  FrictionResponse response(int vertex, const RigidBody& body, const Vec3& x_m,
                            const SurfacePoint& at_x, double normal_force_N,
                            const Vec3& normal_force_gradient_N_per_m = Vec3::Zero(),
                            NearFaces* near = nullptr, bool place_anchor = true) const;
  // Vertex i's offset from its anchor in the tangent plane at x and its derivative.
  TangentialOffset offset(int vertex, const RigidBody& body, const Vec3& x_m,
                          const SurfacePoint& at_x) const {
    return tangential_offset(body, x_m, at_x, anchor_[vertex]);
  }
  double friction_coefficient() const { return mu_; }
  // Keeps the anchor of an accepted state: `response` must be that state's.
  void commit(int vertex, const FrictionResponse& accepted) { anchor_[vertex] = accepted.anchor; }
  // k_t of vertex i, N/m (its contribution to the stiffest vertex of the explicit time step).
  double tangential_stiffness_N_per_m(int vertex) const {
    return tangential_stiffness_Pa_per_m_ * rest_vertex_area_m2_[vertex];
  }

 private:
  double mu_ = 0.0;
  double tangential_stiffness_Pa_per_m_ = 0.0;
  std::vector<double> rest_vertex_area_m2_;
  std::vector<SurfaceLocation> anchor_;
};

}  // namespace tightfit
