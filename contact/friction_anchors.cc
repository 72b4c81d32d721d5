#include "contact/friction_anchors.h"

#include <stdexcept>
#include <utility>

namespace tightfit {

FrictionAnchors::FrictionAnchors(double friction_coefficient, double tangential_stiffness_Pa_per_m,
                                 std::vector<double> rest_vertex_area_m2)
    : mu_(friction_coefficient),
      tangential_stiffness_Pa_per_m_(tangential_stiffness_Pa_per_m),
      rest_vertex_area_m2_(std::move(rest_vertex_area_m2)) {
  if (!(mu_ >= 0.0))
    throw std::invalid_argument("Contact/Friction coefficient: must not be negative");
  if (mu_ > 0.0 && !(tangential_stiffness_Pa_per_m_ > 0.0))
    throw std::invalid_argument("Contact/Tangential penalty ratio: must be positive");
}

void FrictionAnchors::place(const RigidBody& body, const std::vector<Vec3>& positions_m) {
  if (!active()) return;
  anchor_.resize(positions_m.size());
  for (std::size_t i = 0; i < positions_m.size(); ++i)
    anchor_[i] = body.query(positions_m[i]).location;
}

FrictionResponse FrictionAnchors::response(int vertex, const RigidBody& body, const Vec3& x_m,
                                           const SurfacePoint& at_x, double normal_force_N,
                                           const Vec3& normal_force_gradient_N_per_m,
                                           NearFaces* near, bool place_anchor) const {
  CoulombFrictionLaw law;
  law.friction_coefficient = mu_;
  law.tangential_penalty_N_per_m = tangential_stiffness_N_per_m(vertex);
  return coulomb_friction(body, x_m, at_x, normal_force_N, normal_force_gradient_N_per_m,
                          anchor_[vertex], law, near, place_anchor);
}

}  // namespace tightfit
