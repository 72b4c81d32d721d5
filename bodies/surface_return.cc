#include "bodies/surface_return.h"

namespace tightfit {

SurfaceReturn return_onto_surface(const RigidBody& body, std::vector<Vec3>& x,
                                  double allowed_depth_m) {
  SurfaceReturn result;
  std::vector<int> inside;
  for (int v = 0; v < static_cast<int>(x.size()); ++v) {
    const double g = body.query(x[v]).signed_distance_m;
    if (g >= 0.0) continue;
    inside.push_back(v);
    if (-g > result.deepest_m) result.deepest_m = -g, result.deepest_point = v;
  }
  if (result.deepest_m > allowed_depth_m) return result;
  // A step of -g along the distance's gradient reaches a flat face (and an analytic body's
  // surface); near an edge of a faceted body it may fall short, so step again from there. The
  // extra nanometre puts the point just outside rather than on the surface to round-off. Each
  // step at least halves the depth on a mesh body; a few suffice.
  const int most_steps = 16;
  for (int v : inside) {
    SurfacePoint at = body.query(x[v]);
    for (int step = 0; step < most_steps && at.signed_distance_m < 0.0; ++step) {
      x[v] -= (at.signed_distance_m - 1e-9) * at.gap_gradient;
      at = body.query(x[v]);
    }
    ++result.points_moved;
  }
  return result;
}

}  // namespace tightfit
