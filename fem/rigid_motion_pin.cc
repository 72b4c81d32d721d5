#include "fem/rigid_motion_pin.h"

#include "contact/cylinder.h"

#include <cmath>
#include <limits>

namespace tightfit {

RigidMotionPin rigid_motion_pin(const RigidBody& body, const std::vector<Vec3>& positions_m,
                                const ConstrainedDirections& constrained, bool any_constraint) {
  RigidMotionPin pin;
  const auto* cylinder = dynamic_cast<const Cylinder*>(&body);
  if (!cylinder) return pin;
  const Vec3 axis = cylinder->axis().normalized();
  const Vec3 origin = cylinder->point_on_axis_m();
  const int n = static_cast<int>(positions_m.size());
  double mean_axial = 0.0;
  for (const Vec3& x : positions_m) mean_axial += (x - origin).dot(axis);
  mean_axial /= n;
  double best = std::numeric_limits<double>::infinity();
  for (int w = 0; w < n; ++w) {
    const Vec3 r = positions_m[w] - origin;
    const double radial = (r - r.dot(axis) * axis).norm();
    const double distance = std::abs(r.dot(axis) - mean_axial);
    if (!constrained.constrained(w) && radial > 1e-12 && distance < best - 1e-12) {
      best = distance;
      pin.vertex = w;
    }
  }
  if (pin.vertex < 0) return pin;
  const Vec3 r = positions_m[pin.vertex] - origin;
  pin.directions.push_back(axis.cross(r).normalized());
  if (!any_constraint) pin.directions.push_back(axis);
  return pin;
}

}  // namespace tightfit
